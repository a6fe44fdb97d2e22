#include "mpm/particles/particle_generator.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/scene/shape.h"
#include "mpm/mpm_constants.h"

namespace mpmice::mpm {

void generateParticles(const core::Scene& scene, const core::Box& cells, ParticleSet& out,
                       const ContainsFn& contains) {
  const core::Mesh& mesh = scene.mesh;
  const int dim = mesh.dim();
  // Solid objects: (region index, material index).
  std::vector<std::pair<int, int>> solids;
  for (std::size_t r = 0; r < scene.geometry.size(); ++r) {
    const auto& reg = scene.geometry[r];
    for (const auto& f : reg.fill) {
      int m = -1;
      for (std::size_t k = 0; k < scene.materials.size(); ++k)
        if (scene.materials[k].name == f.material) m = static_cast<int>(k);
      if (m < 0 || scene.materials[m].kind != core::MaterialKind::Solid) continue;
      const auto& mat = scene.materials[m];
      if (!(mat.density > 0)) {
        std::ostringstream os;
        os << "materials." << mat.name << ".density: a solid needs a density > 0, got "
           << mat.density << "; give the reference density in kg/m^3";
        throw std::invalid_argument(os.str());
      }
      // Only symmetry faces may cut a solid (beyond them it continues as its mirror image).
      if (const auto bounds = core::scene_detail::shapeBounds(reg.shape, dim)) {
        const auto& [lo, hi] = *bounds;
        for (int d = 0; d < dim; ++d) {
          const double tol = kGeneratorFaceTolerance * (mesh.upper(d) - mesh.origin()[d]);
          const bool symLo = scene.boundary[2 * d].type == core::BoundaryType::Symmetry;
          const bool symHi = scene.boundary[2 * d + 1].type == core::BoundaryType::Symmetry;
          if ((!symLo && lo[d] < mesh.origin()[d] - tol) || (!symHi && hi[d] > mesh.upper(d) + tol)) {
            std::ostringstream os;
            os << "geometry." << reg.name << ": solid '" << mat.name
               << "' reaches outside the mesh in direction " << "xyz"[d] << " ([" << lo[d] << ", "
               << hi[d] << "] vs mesh [" << mesh.origin()[d] << ", " << mesh.upper(d)
               << "]); particles outside the mesh are an error: enlarge the mesh or move the object "
                  "(only symmetry faces may cut a solid)";
            throw std::invalid_argument(os.str());
          }
        }
      }
      for (int d = 0; d < dim; ++d)
        if (reg.particles_per_cell[d] < 1)
          throw std::invalid_argument("geometry." + reg.name + ".particles_per_cell must be >= 1");
      solids.emplace_back(static_cast<int>(r), m);
    }
  }
  if (solids.empty()) return;
  const std::int64_t ncells = mesh.numCells();
  const core::Box all = mesh.cellBox();
  core::forEach(cells, [&](int i, int j, int k) {
    const int ijk[3] = {i, j, k};
    const std::int64_t cellId = all.index(i, j, k);
    for (std::size_t s = 0; s < solids.size(); ++s) {
      const auto& reg = scene.geometry[solids[s].first];
      const int m = solids[s].second;
      int ppc[3] = {1, 1, 1};
      for (int d = 0; d < dim; ++d) ppc[d] = reg.particles_per_cell[d];
      const double vol = mesh.cellVolume() / (ppc[0] * ppc[1] * ppc[2]);
      for (int c = 0; c < ppc[2]; ++c)
        for (int b = 0; b < ppc[1]; ++b)
          for (int a = 0; a < ppc[0]; ++a) {
            const int sub[3] = {a, b, c};
            core::RealVect x{0, 0, 0}, half{0, 0, 0};
            for (int d = 0; d < dim; ++d) {
              x[d] = mesh.node(d, ijk[d]) + (sub[d] + 0.5) * mesh.dx(d) / ppc[d];
              half[d] = 0.5 * mesh.dx(d) / ppc[d];
            }
            if (!contains(reg.shape, x, dim)) continue;
            bool later = false;  // a later solid object claims this point
            for (std::size_t t = s + 1; t < solids.size() && !later; ++t)
              later = solids[t].first != solids[s].first &&
                      contains(scene.geometry[solids[t].first].shape, x, dim);
            if (later) continue;
            const std::int64_t subId = a + 64 * (b + 64 * c);
            const std::int64_t gid =
                ((static_cast<std::int64_t>(s) * ncells + cellId) << 18) + subId;
            out.addParticle(x, reg.velocityAt(x), scene.materials[m].density * vol, vol, half, m,
                            reg.temperature, gid);
          }
    }
  });
}

}  // namespace mpmice::mpm
