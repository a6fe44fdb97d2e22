#pragma once
/// @brief The health check of ICE, once per step in every program (docs/ice.md "Health check").
///
/// Over this rank's owned cells, for every fluid: mass, velocity, specific internal energy,
/// specific volume, volume fraction finite; mass >= 0; specific volume > 0 where there is mass;
/// and where the fluid is present (theta > kPresentFraction) a temperature in (0, kMaxTemperature]
/// and a sound speed (from the compressibility, at the step's equilibrium: soundSpeedSquared) in
/// (0, kMaxSoundSpeed). For every cell: the
/// pressure finite, and the volume fractions of all materials (external ones included) summing to
/// 1 within kFractionSumTolerance. The first violation found is named: quantity, material, cell,
/// cell centre, time, the materials in the cell, and (weakExchangeNote) a weak momentum exchange
/// with a solid nearby.
#include <cmath>
#include <string>

#include "core/health/health.h"
#include "ice/solver/ice_solver.h"

namespace mpmice::ice {

/// |sum_r theta_r - 1| above this is a violation (the equilibrium pressure meets the sum to its
/// tolerance, 1e-11 by default).
inline constexpr double kFractionSumTolerance = 1e-6;

/// The sound speed squared c^2 = v / kappa that the check bounds to (0, kMaxSoundSpeed^2) where a
/// fluid is present: 1 (admissible) for kappa = 0 (a trace held at its carried volume this step,
/// incompressible, docs/ice.md "Traces") and for kappa = inf in a liquid that cavitates (zero
/// sound speed at its cut-off, docs/ice.md "Cavitation"). The equilibrium checks it where it makes
/// kappa (IceSolver::soundSpeedViolations).
inline double soundSpeedSquared(double v, double kappa, bool cavitates) {
  return kappa == 0.0 || (std::isinf(kappa) && kappa > 0 && cavitates) ? 1.0 : v / kappa;
}
inline bool soundSpeedAdmissible(double c2) { return c2 > 0 && c2 < core::kMaxSoundSpeed * core::kMaxSoundSpeed; }

/// The first violation in this rank's owned cells, "" when there is none. Local.
[[nodiscard]] std::string findViolation(const IceSolver& solver);
/// Why a fluid in owned cell (i,j,k) is not held by the solids around it, "" when it is: the
/// external material with the largest volume fraction theta_s in the cell and its owned neighbours
/// (3^dim), and the share of the fluid's velocity difference to it that one step of the momentum
/// exchange removes, dt K theta_s / rho_f (rho_f the fluid's density in the cell). Below 1 the
/// note names the pair, K, the share and the cell: the solid lets the gas through (issue 12, the
/// seed cylinder at K = 0 and 1e3; docs/coupling.md "The seed cylinder at weak exchange").
/// dt: the step to judge it by (< 0: the last step taken, solver.dt()). Local.
[[nodiscard]] std::string weakExchangeNote(const IceSolver& solver, int i, int j, int k, int fluid, double dt = -1);

/// Throws core::HealthError on every rank when any rank finds a violation. Collective.
void checkHealth(const IceSolver& solver);

}  // namespace mpmice::ice
