#pragma once
/// @brief What a scene needs of the machine, estimated before anything is allocated.
///
/// Cells and nodes in checked 64-bit arithmetic; particles from each solid region's bounds (the
/// whole mesh where a shape has none) times its particles per cell; memory from the bytes a
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

/// The estimate of a parsed scene (the mesh's counts are already known to fit).
ResourceEstimate estimateResources(const Scene& scene);

/// Memory this machine has available now [bytes] (MemAvailable; 0 when unknown).
double availableMemory();

}  // namespace mpmice::core
