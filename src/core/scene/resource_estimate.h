#pragma once
/// @brief What a scene needs of the machine, estimated before anything is allocated.
///
/// Cells and nodes in checked 64-bit arithmetic; particles counted by the seeding's own rule
/// (seededParticles); memory from the bytes a
/// solver holds per cell and material, per node and solid, and per particle, measured on this
/// project's solvers (peak resident memory against the count: ICE about 215 bytes per cell and
/// material, MPM about 400 bytes per particle with its grid; docs/benchmarks.md). The estimate
/// is a lower bound: a scene it already puts above the machine's available memory cannot run.
#include <cstdint>
#include <string>

#include "core/scene/scene.h"

namespace mpmice::core {

struct ResourceEstimate {
  std::int64_t cells = 0, nodes = 0, particles = 0;
  double bytes = 0;
  [[nodiscard]] std::string describe() const;  // "1.2e+06 cells, 3.4e+05 particles, ~0.52 GiB"
};

inline constexpr double kBytesPerCellPerMaterial = 200;  // ICE (fluids and solids as materials)
inline constexpr double kBytesPerNodePerSolid = 100;     // MPM grid
inline constexpr double kBytesPerParticle = 300;         // MPM particles

/// The particles mpm_solver's seeding makes (mpm/particles/particle_generator.h): every solid fill
/// entry tests particles_per_cell[d] sub-cell centres per direction in the cells its shape's bounds
/// touch (the whole mesh where unbounded) and keeps a point its shape contains and no later solid
/// object claims. Exact when at most `budget` points (shared by the objects) are tested; above that every k-th
/// point per direction is tested and the count scaled (a mesh of 1e12 cells is estimated, not seeded).
double seededParticles(const Scene& scene, double budget = 2e6);

/// The estimate of a parsed scene (the mesh's counts are already known to fit).
ResourceEstimate estimateResources(const Scene& scene);

/// Memory this machine has available now [bytes] (MemAvailable; 0 when unknown).
double availableMemory();

}  // namespace mpmice::core
