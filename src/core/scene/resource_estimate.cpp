#include "core/scene/resource_estimate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/scene/shape.h"

namespace mpmice::core {

std::string ResourceEstimate::describe() const {
  char b[160];
  std::snprintf(b, sizeof b, "%.3g cells, %.3g particles, about %.3g GiB of memory", double(cells), double(particles),
                bytes / 1073741824.0);
  return b;
}

ResourceEstimate estimateResources(const Scene& scene) {
  ResourceEstimate e;
  const Mesh& mesh = scene.mesh;
  const int dim = mesh.dim();
  e.cells = mesh.numCells();
  e.nodes = 1;
  double cellVolume = 1;
  for (int d = 0; d < dim; ++d) {
    e.nodes *= std::int64_t(mesh.cells()[d]) + 1;
    cellVolume *= mesh.spacing()[d];
  }
  double particles = 0;
  for (const auto& r : scene.geometry) {
    bool solid = false;
    for (const auto& f : r.fill) solid = solid || scene.material(f.material)->kind == MaterialKind::Solid;
    if (!solid) continue;
    double perCell = 1;
    for (int d = 0; d < dim; ++d) perCell *= r.particles_per_cell[d];
    double cells = double(e.cells);
    if (const auto b = scene_detail::shapeBounds(r.shape, dim)) {
      double v = 1;
      for (int d = 0; d < dim; ++d) v *= std::max(0.0, b->second[d] - b->first[d]);
      cells = std::min(cells, v / cellVolume);
    }
    particles += cells * perCell;
  }
  e.particles = static_cast<std::int64_t>(std::min(particles, 9e18));
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
