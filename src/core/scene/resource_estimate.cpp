#include "core/scene/resource_estimate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "core/scene/shape.h"

namespace mpmice::core {

std::string ResourceEstimate::describe() const {
  char b[160];
  std::snprintf(b, sizeof b, "%.3g cells, %.3g particles, about %.3g GiB of memory", double(cells), double(particles),
                bytes / 1073741824.0);
  return b;
}

namespace {

/// Cells [lo, hi] in direction d that a shape's bounds touch (the whole mesh where unbounded).
void boundCells(const Mesh& mesh, const std::optional<std::pair<RealVect, RealVect>>& b, int d, std::int64_t& lo,
                std::int64_t& hi) {
  lo = 0;
  hi = mesh.cells()[d] - 1;
  if (!b) return;
  const auto cell = [&](double x) {
    const double c = std::floor((x - mesh.origin()[d]) / mesh.dx(d));
    return std::int64_t(std::clamp(c, 0.0, double(mesh.cells()[d] - 1)));
  };
  lo = std::max<std::int64_t>(0, cell(b->first[d]) - 1);  // one cell more each side: round-off
  hi = std::min<std::int64_t>(mesh.cells()[d] - 1, cell(b->second[d]) + 1);
}

}  // namespace

double seededParticles(const Scene& scene, double budget) {
  const Mesh& mesh = scene.mesh;
  const int dim = mesh.dim();
  // The seeding's solid objects in its order: (region, material), one per solid fill entry.
  std::vector<std::size_t> solids;
  for (std::size_t r = 0; r < scene.geometry.size(); ++r)
    for (const auto& f : scene.geometry[r].fill) {
      const MaterialSpec* m = scene.material(f.material);
      if (m && m->kind == MaterialKind::Solid) solids.push_back(r);
    }
  const double perObject = std::max(1.0, budget / double(std::max<std::size_t>(1, solids.size())));
  double total = 0;
  for (std::size_t s = 0; s < solids.size(); ++s) {
    const RegionSpec& reg = scene.geometry[solids[s]];
    const auto bounds = scene_detail::shapeBounds(reg.shape, dim);
    // The lattice of candidate points: n[d] = cells the bounds touch x particles per cell.
    std::int64_t lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0}, ppc[3] = {1, 1, 1}, n[3] = {1, 1, 1};
    double points = 1;
    for (int d = 0; d < dim; ++d) {
      boundCells(mesh, bounds, d, lo[d], hi[d]);
      ppc[d] = std::max(1, reg.particles_per_cell[d]);
      n[d] = (hi[d] - lo[d] + 1) * ppc[d];
      points *= double(n[d]);
    }
    // Every k-th point per direction, so that at most perObject points are tested.
    std::int64_t k = 1;
    const auto sampled = [&] {
      double t = 1;
      for (int d = 0; d < dim; ++d) t *= double((n[d] + k - 1) / k);
      return t;
    };
    while (sampled() > perObject) k *= 2;
    double tested = 0, inside = 0;
    std::int64_t p[3] = {0, 0, 0};
    for (p[2] = 0; p[2] < n[2]; p[2] += k)
      for (p[1] = 0; p[1] < n[1]; p[1] += k)
        for (p[0] = 0; p[0] < n[0]; p[0] += k) {
          tested += 1;
          RealVect x{0, 0, 0};
          for (int d = 0; d < dim; ++d)
            x[d] = mesh.node(d, int(lo[d] + p[d] / ppc[d])) +
                   (double(p[d] % ppc[d]) + 0.5) * mesh.dx(d) / double(ppc[d]);
          if (!reg.shape.contains(x, dim)) continue;
          bool later = false;  // a later solid object claims this point
          for (std::size_t t = s + 1; t < solids.size() && !later; ++t)
            later = solids[t] != solids[s] && scene.geometry[solids[t]].shape.contains(x, dim);
          if (!later) inside += 1;
        }
    total += inside * points / tested;
  }
  return total;
}

ResourceEstimate estimateResources(const Scene& scene) {
  ResourceEstimate e;
  const Mesh& mesh = scene.mesh;
  const int dim = mesh.dim();
  e.cells = mesh.numCells();
  e.nodes = 1;
  for (int d = 0; d < dim; ++d) e.nodes *= std::int64_t(mesh.cells()[d]) + 1;
  const double particles = seededParticles(scene);
  e.particles = static_cast<std::int64_t>(std::min(std::round(particles), 9e18));
  const double solids = double(scene.solids().size());
  e.bytes = double(e.cells) * double(scene.materials.size()) * kBytesPerCellPerMaterial +
            double(e.nodes) * solids * kBytesPerNodePerSolid + particles * kBytesPerParticle;
  return e;
}

double availableMemory() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0;
  std::string unit;
  while (in >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb * 1024.0;
  return 0;
}

}  // namespace mpmice::core
