#pragma once
/// @brief The health check of ICE, once per step in every program (docs/ice.md "Health check").
///
/// Over this rank's owned cells, for every fluid: mass, velocity, specific internal energy,
/// specific volume, volume fraction finite; mass >= 0; specific volume > 0 where there is mass;
/// and where the fluid is present (theta > kPresentFraction) a temperature in (0, kMaxTemperature]
/// and a sound speed (from the compressibility) in (0, kMaxSoundSpeed). For every cell: the
/// pressure finite, and the volume fractions of all materials (external ones included) summing to
/// 1 within kFractionSumTolerance. The first violation found is named: quantity, material, cell,
/// cell centre, time.
#include <string>

#include "ice/solver/ice_solver.h"

namespace mpmice::ice {

/// |sum_r theta_r - 1| above this is a violation (the equilibrium pressure meets the sum to its
/// tolerance, 1e-11 by default).
inline constexpr double kFractionSumTolerance = 1e-6;

/// The first violation in this rank's owned cells, "" when there is none. Local.
[[nodiscard]] std::string findViolation(const IceSolver& solver);
/// Throws core::HealthError on every rank when any rank finds a violation. Collective.
void checkHealth(const IceSolver& solver);

}  // namespace mpmice::ice
