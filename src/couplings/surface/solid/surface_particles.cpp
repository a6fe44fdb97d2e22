#include "couplings/surface/solid/surface_particles.h"

#include <algorithm>
#include <numeric>

#include <mpi.h>

namespace mpmice::coupler {

long markSurfaceParticles(mpm::MpmSolver& mpm, int material) {
  const core::Scene& scene = mpm.scene();
  const int dim = scene.mesh.dim();
  const std::string& name = scene.materials[static_cast<std::size_t>(material)].name;
  std::vector<const core::ShapeSpec*> shapes;
  for (const auto& r : scene.geometry)
    for (const auto& f : r.fill)
      if (f.material == name) shapes.push_back(&r.shape);
  auto inside = [&](const core::RealVect& x) {
    return std::any_of(shapes.begin(), shapes.end(), [&](const core::ShapeSpec* s) { return s->contains(x, dim); });
  };
  auto& p = mpm.particles();
  if (!p.layout().surface) {  // the surface columns are stored from the first marking on
    mpm::ParticleLayout layout = p.layout();
    layout.surface = true;
    p.setLayout(layout);
  }
  long count = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.surface[i] = 0.0;
    if (p.material[i] != material) continue;
    bool surface = false;
    for (int d = 0; d < dim && !surface; ++d)
      for (const double s : {-1.0, 1.0}) {
        core::RealVect x{p.x0[0][i], p.x0[1][i], p.x0[2][i]};
        x[d] += s * 2.0 * p.halfSize[d][i];
        if (!inside(x)) {
          surface = true;
          break;
        }
      }
    if (surface) {
      p.surface[i] = 1.0;
      ++count;
    }
  }
  return count;
}

SurfaceCloud gatherSurfaceCloud(const mpm::MpmSolver& mpm) {
  const auto& p = mpm.particles();
  std::vector<double> mine;  // id, x0 (4 per particle)
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.surface[i] != 0.0)
      mine.insert(mine.end(), {static_cast<double>(p.id[i]), p.x0[0][i], p.x0[1][i], p.x0[2][i]});
  const MPI_Comm comm = mpm.comm().raw();
  int n = static_cast<int>(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(mpm.comm().size())), displ(counts.size());
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  int total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    displ[r] = total;
    total += counts[r];
  }
  std::vector<double> all(static_cast<std::size_t>(total));
  MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), displ.data(), MPI_DOUBLE, comm);
  const std::size_t np = all.size() / 4;
  std::vector<std::size_t> order(np);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return all[4 * a] < all[4 * b]; });
  SurfaceCloud c;
  for (const std::size_t k : order) {
    c.ids.push_back(static_cast<std::int64_t>(all[4 * k]));
    c.x0.insert(c.x0.end(), {all[4 * k + 1], all[4 * k + 2], all[4 * k + 3]});
  }
  return c;
}

}  // namespace mpmice::coupler
