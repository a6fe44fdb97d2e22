#pragma once
/// @brief The XDMF 3 index over a run's HDF5 output files, so ParaView opens the time series.
///
/// Holds one record per output step (its time, its HDF5 file and what that file contains) and
/// renders them as two temporal collections, so every ParaView reader (legacy XDMF, Xdmf3 S/T)
/// gives the same two blocks at every time: `mesh`, one structured grid per step (3DCoRectMesh,
/// ORIGIN_DXDYDZ geometry, z,y,x order; cell data Center="Cell", node data Center="Node"), and
/// `particles` (only when particles were written), one Polyvertex grid per step with one vertex per
/// particle (connectivity /particles/xdmf/vertex). 1D and 2D meshes are indexed with two node layers in
/// unused directions (one cell of data there; node data from the companion `grid/node/xdmf/<name>` holding
/// the layer twice); 6-component particle arrays are symmetric tensors indexed as their full 3x3
/// companion `particles/xdmf/<name>` (xx xy xz yx yy yz zx zy zz). The index is plain text; write() replaces
/// the file atomically (write to a temporary, rename).
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
  /// The steps as text (one line each, exact times), for a checkpoint; restore() reads it back
  /// and replaces the steps (a restart continues the index it had).
  [[nodiscard]] std::string serialize() const;
  void restore(const std::string& text);
  [[nodiscard]] std::string text() const;
  void write(const std::string& path) const;

  /// Dataset dims (z,y,x[,ncomp]) of a grid array of this mesh; ncomp 1 gives three dims.
  static std::vector<std::int64_t> gridDims(const Mesh& mesh, Centering c, int ncomp);
  /// Dims the index gives a grid array: gridDims with two node layers in unused directions.
  static std::vector<std::int64_t> xdmfDims(const Mesh& mesh, Centering c, int ncomp);
  /// The dataset the index points at for a grid array ("grid/node/xdmf/v" for node data in 1D/2D).
  static std::string xdmfGridDataset(const Mesh& mesh, Centering c, const std::string& name);

 private:
  Mesh mesh_;
  std::vector<XdmfStep> steps_;
};

}  // namespace mpmice::core
