#include "mpm/solver/startup_check.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/health/health.h"
#include "core/scene/yaml_reader.h"
#include "mpm/grid/boundary_conditions.h"
#include "mpm/particles/particle_generator.h"
#include "mpm/scheme/update_scheme.h"
#include "mpm/shape/shape_function.h"

namespace mpmice::mpm {

namespace {

using core::scene_detail::formatNumber;

}  // namespace

void checkOptions(const core::Scene& scene) {
  if (!(scene.time.cfl > 0 && scene.time.cfl <= 1.0))
    throw std::invalid_argument("time.cfl: the CFL number must lie in (0, 1] for explicit MPM, got " +
                                formatNumber(scene.time.cfl) + "; use e.g. 0.4");
  if (!(scene.mpm.flip >= 0 && scene.mpm.flip <= 1))
    throw std::invalid_argument("mpm.flip: must lie in [0, 1] (1 = FLIP, 0 = PIC), got " + formatNumber(scene.mpm.flip));
  if (!(scene.mpm.damping >= 0))
    throw std::invalid_argument("mpm.damping: must be >= 0 [1/s], got " + formatNumber(scene.mpm.damping));
  (void)parseShapeFunction(scene.mpm.shape_function);
  (void)parseUpdateScheme(scene.mpm.update);
}

std::vector<std::unique_ptr<ConstitutiveModel>> createSolidModels(const core::Scene& scene) {
  std::vector<std::unique_ptr<ConstitutiveModel>> models(scene.materials.size());
  for (std::size_t m = 0; m < scene.materials.size(); ++m) {
    const auto& mat = scene.materials[m];
    if (mat.kind != core::MaterialKind::Solid) continue;
    if (!(mat.density > 0))
      throw std::invalid_argument("materials." + mat.name + ".density: a solid needs a density > 0, got " +
                                  formatNumber(mat.density) + "; give the reference density in kg/m^3");
    models[m] = createConstitutiveModel(mat.constitutive, "materials." + mat.name + ".constitutive");
    const double c = models[m]->waveSpeed(mat.density);
    if (!(c > 0 && c < core::kMaxSoundSpeed))
      throw std::invalid_argument("materials." + mat.name + ": the dilatational wave speed at the reference density (" +
                                  formatNumber(mat.density) + " kg/m^3) is " + formatNumber(c) +
                                  " m/s; expected a speed in (0, speed of light): check the moduli [Pa] and the "
                                  "density [kg/m^3]");
  }
  return models;
}

void checkEverySolidHasParticles(const core::Scene& scene, const std::vector<double>& count) {
  for (const auto& r : scene.geometry)
    for (const auto& f : r.fill) {
      const int m = scene.materialIndex(f.material);
      if (m < 0 || scene.materials[m].kind != core::MaterialKind::Solid || count[static_cast<std::size_t>(m)] > 0)
        continue;
      std::ostringstream os;
      os << "geometry." << r.name << ": solid '" << f.material << "' yields no particle: its shape holds no "
         << "particle position of the mesh (cell size / particles_per_cell); enlarge the shape, refine the mesh "
         << "or raise particles_per_cell";
      throw std::invalid_argument(os.str());
    }
}

int loadMaterial(const core::Scene& scene, std::size_t l,
                 const std::vector<std::unique_ptr<ConstitutiveModel>>& models) {
  const auto& ld = scene.loads[l];
  for (std::size_t m = 0; m < scene.materials.size(); ++m)
    if (scene.materials[m].name == ld.material && models[m]) return static_cast<int>(m);
  throw std::invalid_argument("loads[" + std::to_string(l) + "].material: '" + ld.material +
                              "' is not a solid material of the scene");
}

void validateStartup(const core::Scene& scene) {
  checkOptions(scene);
  const core::Mesh& mesh = scene.mesh;
  const BoundaryConditions bcs(scene.boundary, mesh, mesh.nodeBox());
  const auto models = createSolidModels(scene);
  // Particles slab by slab along the last direction: the memory of one slab, not of the scene.
  const core::Box all = mesh.cellBox();
  const int last = mesh.dim() - 1;
  std::vector<double> count(scene.materials.size(), 0.0);
  for (int s = all.lo[last]; s <= all.hi[last]; ++s) {
    core::Box slab = all;
    slab.lo[last] = slab.hi[last] = s;
    ParticleSet p;
    generateParticles(scene, slab, p, [](const core::ShapeSpec& shape, const core::RealVect& x, int dim) {
      return shape.contains(x, dim);
    });
    for (std::size_t i = 0; i < p.size(); ++i) count[static_cast<std::size_t>(p.material[i])] += 1.0;
  }
  checkEverySolidHasParticles(scene, count);
  for (std::size_t l = 0; l < scene.loads.size(); ++l) (void)loadMaterial(scene, l, models);
}

}  // namespace mpmice::mpm
