#pragma once
/// @brief How one coupled step is taken in memory: the schedules of the scene's coupling section.
///
///   monolithic         the seed's in-step sequence, four exchange points (A, B, C, D)
///   explicit_serial    the solid steps with the fluid's last B, D; the fluid then steps with the
///                      solid's new A, C (Gauss-Seidel), once
///   explicit_parallel  both step with the other's last values (Jacobi), once
///   implicit_serial    explicit_serial repeated from a checkpoint of both solvers until the
///                      acceptance checks on the fluid's output (B, D) pass; accelerated
///   implicit_parallel  explicit_parallel repeated likewise on (A, C, B, D)
/// Chosen by name (makeSchedule); an unknown name is an error listing the valid ones.
#include <memory>
#include <string>
#include <vector>

#include "couplings/volume/common/implicit_iteration.h"
#include "couplings/volume/fluid/fluid_side.h"
#include "couplings/volume/solid/solid_side.h"

namespace mpmice::coupler {

class CouplingSchedule {
 public:
  virtual ~CouplingSchedule() = default;
  virtual StepReport step(SolidSide& solid, FluidSide& fluid, double dt) = 0;
  [[nodiscard]] virtual const char* name() const = 0;
  /// Names of the measured fields (the CSV columns of the residuals).
  [[nodiscard]] virtual std::vector<std::string> measuredFields() const { return {}; }
};

/// The schedule named in scene.coupling.schedule, with its acceptance checks and acceleration.
std::unique_ptr<CouplingSchedule> makeSchedule(const core::Scene& scene, const core::Comm& comm);
const std::vector<std::string>& scheduleNames();

/// Copies the named exchange point's fields from one side's set to the other's.
void transfer(const std::vector<SolidExchangeFields>& from, std::vector<SolidExchangeFields>& to, char point);

}  // namespace mpmice::coupler
