#pragma once
/// @brief MpmOutput: writes the MPM state of one output step through core::OutputWriter (one
/// parallel HDF5 file per step plus the XDMF index, docs/output-format.md).
///
/// Particles (unless output.particles is false): position, velocity (3), stress (6: xx, yy, zz,
/// xy, yz, xz), deformation_gradient (9, row-major), plastic_strain, mass, volume, material (the
/// index into the scene's materials, as a double), id. Grid nodes: mass and velocity (v_n of the
/// last particle-to-grid pass). output.fields, when not empty, selects among these names (grid and
/// particle arrays alike; position is always written). Collective: every rank calls write().
#include <string>
#include <vector>

#include "core/io/output_writer.h"
#include "mpm/solver/mpm_solver.h"

namespace mpmice::mpm {

class MpmOutput {
 public:
  /// Output into scene.output.directory, files named after scene.name. Collective.
  explicit MpmOutput(const MpmSolver& solver);

  /// Writes the solver's current state as output step solver.stepCount(); returns the file path.
  std::string write(const MpmSolver& solver);
  [[nodiscard]] std::string xdmfPath() const { return writer_.xdmfPath(); }
  /// The XDMF index so far (for a checkpoint) and its restart (core::OutputWriter::resumeIndex).
  [[nodiscard]] std::string indexState() const { return writer_.index().serialize(); }
  void resumeIndex(const std::string& serialized) { writer_.resumeIndex(serialized); }
  /// Every array name MpmOutput can write (grid and particles), for output.fields.
  static const std::vector<std::string>& fieldNames();

 private:
  [[nodiscard]] bool wanted(const std::string& name) const;

  core::OutputWriter writer_;
  std::vector<std::string> fields_;
  bool particles_;
  std::vector<double> materialId_, id_;  // int columns as doubles (reused)
  core::Field nodeVelocity3_;  // 1D / 2D: the node velocity with its zero components, as written
};

}  // namespace mpmice::mpm
