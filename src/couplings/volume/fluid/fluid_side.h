#pragma once
/// @brief The fluid (ICE) side of an MPM-ICE step, in the order of the monolithic-style schedule.
///
///   consumeAProduceB(dt)  the solids' cell state enters as external materials (the first time,
///                         the fluids are fitted to the volume the solids leave free); equilibrium
///                         pressure; face velocities; pressure increment; face pressure;
///                         pressure force on each solid
///   consumeCProduceD()    sources and Lagrangian values; the solids' Lagrangian momentum;
///                         pointwise implicit exchange; exchange increments of each solid
///   finishStep()          fluids advected (the solids advect themselves)
#include <vector>

#include "couplings/volume/common/exchange_fields.h"
#include "couplings/volume/common/run_output.h"
#include "ice/solver/ice_solver.h"

namespace mpmice::coupler {

class FluidSide {
 public:
  FluidSide(ice::IceSolver& ice, const core::Scene& scene);

  [[nodiscard]] double stableTimeStep() const { return ice_.stableTimeStep(); }
  void consumeAProduceB(double dt);
  void consumeCProduceD();
  void finishStep();
  /// Before the first step, with the solids' initial state in A: the solids enter as external
  /// materials and the fluids are fitted to the volume they leave free (see consumeAProduceB).
  void start();
  /// Sets B to the equilibrium pressure with the solids placed and no force, D to zero (before a first step).
  void primeOutput();
  /// A whole step with the A and C fields as they are (partitioned schedules); produces B and D.
  void fullStep(double dt);

  [[nodiscard]] std::vector<SolidExchangeFields>& fields() { return fields_; }
  [[nodiscard]] ice::IceSolver& solver() { return ice_; }
  /// Mass, momentum and energy (internal + kinetic) of the fluids (collective).
  [[nodiscard]] SideTotals totals() const;
  /// The solver, the held exchange fields and whether the start is done under `prefix`, for a
  /// checkpoint; load puts them back.
  void saveCheckpoint(core::CheckpointData& data, const std::string& prefix) const {
    ice_.saveCheckpoint(data, prefix + ".ice");
    saveExchangeFields(fields_, data, prefix + ".exchange");
    data.put(prefix + ".started", started_ ? 1.0 : 0.0);
  }
  void loadCheckpoint(const core::CheckpointData& data, const std::string& prefix) {
    ice_.loadCheckpoint(data, prefix + ".ice");
    loadExchangeFields(fields_, data, prefix + ".exchange");
    started_ = data.scalar(prefix + ".started") != 0.0;
  }

 private:
  static std::span<const double> all(const core::Field& f) {
    return {f.data(), static_cast<std::size_t>(f.npts() * f.ncomp())};
  }
  /// Every solid's cell state (and face transport) into ICE.
  void setSolidStates();

  ice::IceSolver& ice_;
  bool faceTransport_;  // coupling.solid_transport mpm: the solid state carries the face transport
  std::vector<SolidExchangeFields> fields_;
  bool started_ = false;  // the first step fits the fluids to the solids' volume
};

}  // namespace mpmice::coupler
