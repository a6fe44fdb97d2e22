#include "ice/solver/startup_check.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/mesh/box.h"
#include "ice/ice_constants.h"
#include "ice/solver/initial_regions.h"

namespace mpmice::ice {

std::unique_ptr<Eos> makeMaterialEos(const core::MaterialSpec& ms) {
  std::unique_ptr<Eos> eos;
  try {
    eos = makeEos(ms.eos, ms.specific_heat);
  } catch (const std::exception& e) {
    badInput(ms.eos.where, "materials." + ms.name + ".eos: " + e.what());
  }
  if (!ms.cavitation.type.empty()) {  // the schema checked the model name and the liquid EOS
    if (ms.cavitation.type != "pressure_cutoff")
      badInput(ms.cavitation.where, "materials." + ms.name + ".cavitation.model: unknown model '" +
                                        ms.cavitation.type + "'; valid: pressure_cutoff");
    const double pc = ms.cavitation.has("pressure") ? ms.cavitation.get("pressure") : std::nan("");
    if (!std::isfinite(pc))
      badInput(ms.cavitation.where, "materials." + ms.name + ".cavitation.pressure: a finite cut-off pressure [Pa] is required");
    double floor = 0;
    const double e = eos->internalEnergy(eos->densityFromPT(kReferencePressure, kReferenceTemperature), kReferencePressure);
    eos->pressureFloor(1, &e, &floor);
    if (!(pc > floor))
      badInput(ms.cavitation.where, "materials." + ms.name + ".cavitation.pressure = " + std::to_string(pc) +
                                        " Pa lies at or below the lowest pressure of its equation of state (" +
                                        std::to_string(floor) + " Pa)");
    eos->setCavitationPressure(pc);
  }
  return eos;
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
