#pragma once
/// @brief The start-up validation of the ICE solver that `coupler check` shares: each material's
/// equation of state, the geometry objects and each fluid's state in them (initial_regions.h),
/// and the cover of every cell, over the whole mesh on one process (no MPI).
///
/// IceSolver::initialize calls the same functions for the cells of its rank. Each rule throws
/// std::invalid_argument naming the scene key (material, region, cell) and what was expected.
#include <memory>

#include "core/scene/scene.h"
#include "ice/eos/eos.h"

namespace mpmice::ice {

/// The equation of state of a material (solids: their solid_bulk EOS); errors name materials.<name>.eos.
std::unique_ptr<Eos> makeMaterialEos(const core::MaterialSpec& material);

/// Every rule above for the whole mesh.
void validateStartup(const core::Scene& scene);

}  // namespace mpmice::ice
