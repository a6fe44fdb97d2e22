#pragma once
/// @brief The XDMF 3 index over a run's HDF5 output files, so ParaView opens the time series.
///
/// Holds one record per output step (its time, its HDF5 file and what that file contains) and
/// renders them as a temporal collection: each step is a spatial collection of a structured grid
/// (3DCoRectMesh, ORIGIN_DXDYDZ geometry, z,y,x order; cell data Center="Cell", node data
/// Center="Node") and, when particles were written, a Polyvertex grid of the particles. 1D and 2D
/// meshes use the same 3D layout with one node (and one cell of data) in unused directions. The
/// index is plain text; write() replaces the file atomically (write to a temporary, rename).
#include <cstdint>
#include <string>
#include <vector>

#include "core/mesh/mesh.h"
#include "core/parallel/decomposition.h"

namespace mpmice::core {

struct XdmfStep {
  struct GridArray {
    std::string name;
    Centering centering = Centering::Cell;
    int ncomp = 1;
  };
  struct ParticleArray {
    std::string name;
    int ncomp = 1;
  };
  int step = 0;
  double time = 0.0;
  std::string h5file;  ///< relative to the .xmf file's directory
  std::vector<GridArray> grid;
  std::int64_t numParticles = -1;  ///< -1: no particles in this step
  std::vector<ParticleArray> particles;
};

class XdmfWriter {
 public:
  explicit XdmfWriter(const Mesh& mesh) : mesh_(mesh) {}

  /// Appends a step; steps numbered at or after it are dropped first (a restart rewrites them).
  void add(XdmfStep s);
  [[nodiscard]] const std::vector<XdmfStep>& steps() const { return steps_; }
  [[nodiscard]] std::string text() const;
  void write(const std::string& path) const;

  /// Dataset dims (z,y,x[,ncomp]) of a grid array of this mesh; ncomp 1 gives three dims.
  static std::vector<std::int64_t> gridDims(const Mesh& mesh, Centering c, int ncomp);

 private:
  Mesh mesh_;
  std::vector<XdmfStep> steps_;
};

}  // namespace mpmice::core
