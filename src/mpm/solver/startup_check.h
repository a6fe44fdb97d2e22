#pragma once
/// @brief The start-up validation of the MPM solver: the rules mpm_solver applies to a scene
/// before its first step, as the functions MpmSolver's constructor calls, and all of them at once
/// over the whole mesh on one process for `coupler check` (validateStartup).
///
/// Each rule throws std::invalid_argument naming the scene key (material, region, load) and what
/// was expected. No MPI: validateStartup runs in a process that never initialises it.
#include <memory>
#include <vector>

#include "core/scene/scene.h"
#include "mpm/material/constitutive_model.h"

namespace mpmice::mpm {

/// time.cfl in (0, 1], mpm.flip in [0, 1], mpm.damping >= 0, mpm.shape_function, mpm.update.
void checkOptions(const core::Scene& scene);

/// The constitutive model of every solid material (nullptr for fluids), in scene order: a density
/// > 0, elastic constants whose derived values are finite (ElasticConstants::fromSpec) and a
/// dilatational wave speed at the reference density below the speed of light.
std::vector<std::unique_ptr<ConstitutiveModel>> createSolidModels(const core::Scene& scene);

/// A solid the scene places but no particle represents (a shape smaller than the particles'
/// spacing) is an error naming its region. `count[m]`: particles of material m on all ranks.
void checkEverySolidHasParticles(const core::Scene& scene, const std::vector<double>& count);

/// The material index of loads[l]: a solid of the scene (`models` from createSolidModels).
int loadMaterial(const core::Scene& scene, std::size_t l,
                 const std::vector<std::unique_ptr<ConstitutiveModel>>& models);

/// Every rule above (and the boundary conditions' and particle generation's) for the whole mesh
/// on this process: particles are generated a slab of cells at a time, counted and dropped.
void validateStartup(const core::Scene& scene);

}  // namespace mpmice::mpm
