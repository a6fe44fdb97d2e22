#pragma once
/// @brief The health check of ICE, once per step in every program (docs/ice.md "Health check").
///
/// Over this rank's owned cells, for every fluid: mass, velocity, specific internal energy,
/// specific volume, volume fraction finite; mass >= 0; specific volume > 0 where there is mass;
/// and where the fluid is present (theta > kPresentFraction) a temperature in (0, kMaxTemperature]
/// and a sound speed (from the compressibility) in (0, kMaxSoundSpeed). For every cell: the
/// pressure finite, and the volume fractions of all materials (external ones included) summing to
/// 1 within kFractionSumTolerance. The first violation found is named: quantity, material, cell,
/// cell centre, time, the materials in the cell, and (weakExchangeNote) a weak momentum exchange
/// with a solid nearby.
#include <string>

#include "ice/solver/ice_solver.h"

namespace mpmice::ice {

/// |sum_r theta_r - 1| above this is a violation (the equilibrium pressure meets the sum to its
/// tolerance, 1e-11 by default).
inline constexpr double kFractionSumTolerance = 1e-6;

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
