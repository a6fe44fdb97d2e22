#include "ice/solver/startup_check.h"

#include <stdexcept>
#include <vector>

#include "core/mesh/box.h"
#include "ice/solver/initial_regions.h"

namespace mpmice::ice {

std::unique_ptr<Eos> makeMaterialEos(const core::MaterialSpec& ms) {
  try {
    return makeEos(ms.eos, ms.specific_heat);
  } catch (const std::exception& e) {
    badInput(ms.eos.where, "materials." + ms.name + ".eos: " + e.what());
  }
}

void validateStartup(const core::Scene& scene) {
  if (scene.materials.empty()) throw std::invalid_argument("materials: the scene has no material");
  std::vector<std::unique_ptr<Eos>> owned;
  std::vector<const Eos*> eos;
  for (const core::MaterialSpec& m : scene.materials) {
    owned.push_back(makeMaterialEos(m));
    eos.push_back(owned.back().get());
  }
  const RegionPlan plan = planRegions(scene, eos);
  const core::Mesh& mesh = scene.mesh;
  const int dim = mesh.dim();
  core::forEach(mesh.cellBox(), [&](int i, int j, int k) {
    const core::RealVect x{mesh.cellCenter(0, i), dim > 1 ? mesh.cellCenter(1, j) : 0.0,
                           dim > 2 ? mesh.cellCenter(2, k) : 0.0};
    requireCovered(plan, coverAt(plan, x, dim), i, j, k);
  });
}

}  // namespace mpmice::ice
