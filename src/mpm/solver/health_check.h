#pragma once
/// @brief The health check of MPM, once per step in every program (docs/mpm.md "Health check").
///
/// Over this rank's particles: position, velocity, stress and stress work finite; mass and volume
/// finite and > 0 (the volume's message gives J = det F = V / V0); temperature in
/// (0, kMaxTemperature]; the material's wave speed at the particle's density in (0, kMaxSoundSpeed).
/// The first violation found is named: quantity, material, particle id, position, time. Then per
/// material, its stored stress work (elastic + dissipated, >= 0 physically) not below minus its
/// kinetic energy and the elastic energy of a 1 % strain (what an unstable step does to the books:
/// health_check.cpp); the particle with the most negative work is named.
#include <string>

#include "mpm/solver/mpm_solver.h"

namespace mpmice::mpm {

/// The first violation among this rank's particles, "" when there is none. Local. With `where`
/// (3 doubles), the violating particle's position goes there (unused directions 0).
[[nodiscard]] std::string findViolation(const MpmSolver& solver, double* where = nullptr);
/// Throws core::HealthError on every rank when any rank finds a violation. Collective.
void checkHealth(const MpmSolver& solver);

}  // namespace mpmice::mpm
