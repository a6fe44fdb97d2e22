#pragma once
/// @brief The monolithic driver: libmpm and libice in one process, in-memory exchange.
///
/// The reference that partitioned MPMD runs are measured against: the same SolidSide and
/// FluidSide objects as the MPMD participants, with the exchange points turned into copies.
/// The step follows the scene's coupling.schedule (schedule/coupling_schedule.h): the seed's
/// monolithic-style sequence or a partitioned explicit or implicit one. Both solvers share the
/// communicator and hence the decomposition.
#include <functional>
#include <ostream>

#include "couplings/volume/fluid/fluid_side.h"
#include "couplings/volume/schedule/coupling_schedule.h"
#include "couplings/volume/solid/solid_side.h"

namespace mpmice::coupler {

class MonolithicDriver {
 public:
  MonolithicDriver(const core::Scene& scene, const core::Comm& comm);
  ~MonolithicDriver();

  /// One coupled step of size dt (<= the stable step of both sides).
  void step(double dt);
  /// The stable step of both sides, capped by dt_max and the time left to `until`.
  [[nodiscard]] double nextTimeStep(double until) const;
  /// Steps to `until` (default: time.end), calling `afterStep` after each step.
  void run(double until, const std::function<void()>& afterStep = {});

  [[nodiscard]] double time() const { return t_; }
  [[nodiscard]] long steps() const { return n_; }
  [[nodiscard]] mpm::MpmSolver& mpm() { return *mpm_; }
  [[nodiscard]] ice::IceSolver& ice() { return *ice_; }
  [[nodiscard]] SolidSide& solid() { return *solid_; }
  [[nodiscard]] FluidSide& fluid() { return *fluid_; }
  [[nodiscard]] const CouplingSchedule& schedule() const { return *schedule_; }
  [[nodiscard]] const StepReport& lastReport() const { return last_; }

 private:
  const core::Scene& scene_;
  std::unique_ptr<mpm::MpmSolver> mpm_;
  std::unique_ptr<ice::IceSolver> ice_;
  std::unique_ptr<SolidSide> solid_;
  std::unique_ptr<FluidSide> fluid_;
  std::unique_ptr<CouplingSchedule> schedule_;
  StepReport last_;
  double t_ = 0;
  long n_ = 0;
};

}  // namespace mpmice::coupler
