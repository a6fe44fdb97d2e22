#pragma once
/// @brief Writes a run's output steps: one parallel HDF5 file per step plus an XDMF index.
///
/// writeStep() is collective over the Comm: every rank passes the same field names (in the same
/// order) and, if any rank passes particles, every rank does (possibly with zero particles). The
/// file `<dir>/<base>_<step:06d>.h5` holds each grid Field as a global dataset
/// `/grid/cell/<name>` or `/grid/node/<name>` of shape (nz, ny, nx) (x fastest, C order), with a
/// trailing component dimension when ncomp > 1; each rank writes only its owned region
/// (Decomposition::ownedBox) as a hyperslab, in one collective H5Dwrite per dataset. 1D and 2D
/// meshes use the same 3D layout with extent 1 in unused directions. In periodic directions the
/// closing node layer (node n, the image of node 0) is written from the owner of node 0, so node
/// datasets always have n+1 nodes. Particles are concatenated in rank order under `/particles/`
/// (`position` is (n, 3); scalars (n); vectors (n, ncomp)). The root group carries the
/// attributes time, step, dim, origin, spacing, cells, periodic and nranks, and, inside a run, the
/// run's description (core/io/run_metadata.h: program, version, command line, ranks, rank layout,
/// host, start, scene file, hash and the scene as understood). After each file, rank 0
/// rewrites `<dir>/<base>.xmf` over all steps written so far (see XdmfWriter). The layout is
/// documented in docs/output-format.md.
#include <string>
#include <vector>

#include "core/field/field.h"
#include "core/io/particle_output.h"
#include "core/io/xdmf_writer.h"
#include "core/parallel/comm.h"
#include "core/parallel/decomposition.h"

namespace mpmice::core {

class H5Group;

class OutputWriter {
 public:
  /// Creates `directory` (rank 0, then a barrier) when missing. Collective.
  OutputWriter(const Comm& comm, const Decomposition& decomp, std::string directory, std::string baseName);

  /// Writes one step (collective); returns the path of the HDF5 file written. Each field must store
  /// at least its owned region (decomp.ownedBox(rank, field.centering())).
  std::string writeStep(int step, double time, const std::vector<const Field*>& gridFields,
                        const ParticleOutput* particles = nullptr);

  /// `<dir>/<base>_<step:06d>.h5`
  [[nodiscard]] std::string stepPath(int step) const;
  /// `<dir>/<base>.xmf`
  [[nodiscard]] std::string xdmfPath() const;
  [[nodiscard]] const XdmfWriter& index() const { return xdmf_; }
  /// A restart: continues the index of the steps written before the checkpoint (the text
  /// XdmfWriter::serialize() gave then) and rewrites `<base>.xmf` over them (rank 0). Collective.
  void resumeIndex(const std::string& serialized);

 private:
  void writeGridField(const H5Group& group, const Field& f) const;
  void writeIndex() const;  // rank 0 rewrites <base>.xmf (collective: every rank learns a failure)
  void writeParticles(const H5Group& root, const ParticleOutput& p) const;

  Comm comm_;
  Decomposition decomp_;
  std::string dir_, base_;
  XdmfWriter xdmf_;
};

}  // namespace mpmice::core
