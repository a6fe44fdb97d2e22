#pragma once
/// @brief The sequential workflow with files: a scene's `file` loads (a fluid code's exported
/// point forces, core/io/force_export_file.h) mapped conservatively onto a solid's surface
/// particles and held there for the whole run of mpm_solver alone.
///
/// Per load: the surface particles of `material` (surface_particles.h, the outer layer), the
/// scene's mapping (coupler/mapping: nearest_neighbor, or rbf, which keeps the total moment too)
/// from the particles' initial positions to the file's points, f_particles = M^T f_points; in 2D
/// the forces are divided by the depth (the load's `depth`, else the file's "# Depth [m]:", else
/// 1 m) and their z parts dropped. The report (rank 0) gives, per load, the total force and the
/// moment about `moment_center` read from the file and applied to the particles (in 2D times the
/// depth, so both are in the file's units).
#include <array>
#include <ostream>
#include <vector>

#include "mpm/solver/mpm_solver.h"

namespace mpmice::coupler {

struct FileLoadReport {
  std::array<double, 3> forceRead{}, momentRead{}, forceApplied{}, momentApplied{};
  std::size_t points = 0;
  long long particles = 0;
  int phases = 0;
  double depth = 1;  // 2D: the depth the forces were divided by
};

/// Reads and maps every file load of the solver's scene onto fsurf (collective). Throws
/// std::invalid_argument naming the file (and line) for a bad file, or the load for a material
/// without particles. Prints one report per load to `log` on rank 0.
std::vector<FileLoadReport> applyFileLoads(mpm::MpmSolver& mpm, std::ostream& log);

}  // namespace mpmice::coupler
