#pragma once
/// @brief The solid (MPM) side of an MPM-ICE step, in the order of the monolithic-style schedule.
///
///   beginStep(dt) + produceA()   particles to grid; cell mass, velocity, temperature, specific volume
///   consumeB() + produceC()      internal forces with the mean-stress correction (sigma + (p - p_ref) I)
///                                + the fluid's pressure force; grid update;
///                                cell Lagrangian momentum and the work those forces did
///   consumeD() + finishStep()    exchange increments to the nodes (the kinetic energy the nodes
///                                do not take becomes heat); exchange heat to the particles;
///                                particles updated; migration
/// The same object serves the in-process driver (mpmice) and the MPMD participant (mpm_solver):
/// only the transport of the fields differs, so both give the same numbers.
#include <vector>

#include "core/io/particle_output.h"
#include "couplings/volume/common/exchange_fields.h"
#include "couplings/volume/common/run_output.h"
#include "mpm/solver/mpm_solver.h"

namespace mpmice::coupler {

class SolidSide {
 public:
  explicit SolidSide(mpm::MpmSolver& mpm);

  [[nodiscard]] double stableTimeStep() const { return mpm_.stableTimeStep(); }
  void beginStep(double dt);
  void produceA();
  void consumeBProduceC();
  void consumeDFinishStep();
  /// A whole step with the B and D fields as they are (partitioned schedules: the fluid's last
  /// values); produces A and C.
  void fullStep(double dt);

  [[nodiscard]] std::vector<SolidExchangeFields>& fields() { return fields_; }
  [[nodiscard]] mpm::MpmSolver& solver() { return mpm_; }
  /// Mass, momentum and energy (kinetic + stress work) of the particles (collective).
  [[nodiscard]] SideTotals totals() const;
  /// The particle arrays for the OutputWriter (views into the solver's storage; the material
  /// index and the global id as doubles, as mpm_solver writes them, kept here).
  [[nodiscard]] core::ParticleOutput particleOutput() const;
  /// The solver and the held exchange fields under `prefix`, for a checkpoint; load puts them back.
  void saveCheckpoint(core::CheckpointData& data, const std::string& prefix) const {
    mpm_.saveCheckpoint(data, prefix + ".mpm");
    saveExchangeFields(fields_, data, prefix + ".exchange");
  }
  void loadCheckpoint(const core::CheckpointData& data, const std::string& prefix) {
    mpm_.loadCheckpoint(data, prefix + ".mpm");
    loadExchangeFields(fields_, data, prefix + ".exchange");
  }

 private:
  mpm::MpmSolver& mpm_;
  bool faceTransport_;  // coupling.solid_transport mpm: the solid state carries the face transport
  std::vector<SolidExchangeFields> fields_;
  mutable std::vector<double> materialOut_, idOut_;  // particleOutput's material index and id
};

}  // namespace mpmice::coupler
