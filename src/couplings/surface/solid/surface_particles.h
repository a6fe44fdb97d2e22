#pragma once
/// @brief The surface particles of a solid: those a surface-coupled fluid's forces act on.
///
/// A particle of material m is on the surface when one of its lattice neighbours (one particle
/// spacing, 2 halfSize, away along +-x, +-y, +-z) lies outside every geometry region that m
/// fills: the outer layer of particles, whatever the shape. Marked in the particle column
/// `surface` (1 or 0), which travels with the particle through sorting and migration.
#include <cstdint>
#include <vector>

#include "mpm/solver/mpm_solver.h"

namespace mpmice::coupler {

/// Marks the surface particles of `material` (local). Returns the local count.
long markSurfaceParticles(mpm::MpmSolver& mpm, int material);

/// The surface particles of all ranks, in a fixed global order (by id): ids and positions at t = 0.
struct SurfaceCloud {
  std::vector<std::int64_t> ids;
  std::vector<double> x0;  // 3 per particle
  [[nodiscard]] std::size_t size() const { return ids.size(); }
};
/// Collective over the solver's communicator.
SurfaceCloud gatherSurfaceCloud(const mpm::MpmSolver& mpm);

}  // namespace mpmice::coupler
