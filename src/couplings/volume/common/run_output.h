#pragma once
/// @brief What a coupled run writes: HDF5/XDMF fields and particles at each output time
/// (core::OutputSchedule says when), and a
/// CSV conservation monitor (total mass, momentum and energy of the solids and the fluids).
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "core/io/checkpoint.h"
#include "core/io/csv_writer.h"
#include "core/io/output_writer.h"
#include "core/io/particle_output.h"
#include "core/scene/scene.h"

namespace mpmice::coupler {

/// Totals of one side: mass, momentum (3) and the energy by kind (docs/coupling.md "Energy
/// budget"): kinetic; internal (fluid: internal energy; solid: stress work, elastic + plastic);
/// heat (solid: sum m cv T of the particles); and what the solid's method itself created (> 0) or
/// removed (MpmSolver Energies: particle-grid transfer, stress integration, damping); the mass and
/// energy the particles removed through outflow faces carried out (mpm.outflow_particles), which
/// count as removed.
struct SideTotals {
  double mass = 0;
  std::array<double, 3> momentum{0, 0, 0};
  double kinetic = 0, internal = 0, heat = 0;
  double transfer = 0, integration = 0, damping = 0;
  double massOut = 0, energyOut = 0;
  [[nodiscard]] double energy() const { return kinetic + internal + heat; }
  [[nodiscard]] double created() const { return transfer + integration + damping - energyOut; }
  [[nodiscard]] std::vector<double> pack() const {
    return {mass,     momentum[0], momentum[1], momentum[2], kinetic, internal,
            heat,     transfer,    integration, damping,     massOut, energyOut};
  }
  static SideTotals unpack(const std::vector<double>& v);
};

class RunOutput {
 public:
  /// Writes under scene.output.directory as <name><suffix>_*.h5 (nothing when output.enabled is
  /// false). writeCsv: this writer also keeps the conservation CSV.
  /// resumed: a restart continues the XDMF index and the CSV as they were at that checkpoint
  /// (what save() put there).
  RunOutput(const core::Scene& scene, const core::Comm& comm, const core::Decomposition& decomp,
            const std::string& suffix = "", bool writeCsv = true, const core::CheckpointData* resumed = nullptr);
  /// The index and the CSV length, for a checkpoint.
  void save(core::CheckpointData& data) const;
  void writeFields(long step, double time, const std::vector<const core::Field*>& fields,
                   const core::ParticleOutput* particles);
  void writeTotals(long step, double time, const SideTotals& solid, const SideTotals& fluid);

 private:
  const core::Scene& scene_;
  bool enabled_;
  std::unique_ptr<core::OutputWriter> writer_;
  std::unique_ptr<core::CsvWriter> csv_;
};

}  // namespace mpmice::coupler
