#pragma once
/// @brief How one coupled MPM-ICE step is taken: the schedules of the scene's coupling section.
///
///   monolithic         the seed's in-step sequence: four exchange points per step
///                      (monolithic_schedule.cpp)
///   explicit_serial    the solid steps with the fluid's last pressure force and exchange
///                      increments; the fluid then steps with the solid's new state (Gauss-Seidel)
///   explicit_parallel  both step with the other's last values (Jacobi)  (explicit_schedule.cpp)
///   implicit_serial    explicit_serial repeated from a checkpoint of both solvers until the
///                      acceptance checks on the fluid's output pass; accelerated
///   implicit_parallel  explicit_parallel repeated likewise on every exchanged field
///                                                                        (implicit_schedule.cpp)
/// Each schedule's order of exchange points is written once, in its file, against Sides and a
/// Transport: the in-process driver (both sides, InMemoryTransport) and the MPMD programs (one
/// side, MpiTransport) run the same code. The start of a run is common to all (startCoupling).
#include <memory>
#include <string>
#include <vector>

#include "coupler/iteration/implicit_iteration.h"
#include "couplings/volume/schedule/sides.h"

namespace mpmice::coupler {

class CouplingSchedule {
 public:
  virtual ~CouplingSchedule() = default;
  /// One step of size dt over the sides this process holds.
  virtual StepReport step(const Sides& sides, Transport& transport, double dt) = 0;
  [[nodiscard]] virtual core::Schedule kind() const = 0;
  /// Names of the measured fields (the CSV columns of the residuals).
  [[nodiscard]] virtual std::vector<std::string> measuredFields() const { return {}; }
  /// What the schedule carries from step to step (partitioned: whether the first step is done;
  /// implicit: the acceleration's history), for a checkpoint between steps. Local.
  virtual void save(core::CheckpointData& /*data*/, const std::string& /*prefix*/) const {}
  virtual void load(const core::CheckpointData& /*data*/, const std::string& /*prefix*/) {}
};

/// The schedule of scene.coupling.schedule, with its acceptance checks and acceleration.
std::unique_ptr<CouplingSchedule> makeSchedule(const core::Scene& scene, const core::Comm& comm);

/// The start of every run: the fluid takes the solids' initial cell state and fits its fluids
/// to the volume they leave free (before any checkpoint, so implicit schedules repeat steps from
/// that state); the solid gets the fluid's initial pressure and no force or exchange yet
/// (partitioned schedules step the solid first with the fluid's last output).
void startCoupling(const Sides& sides, Transport& transport);

}  // namespace mpmice::coupler
