#pragma once
/// @brief The update scheme (`mpm.update`): when the particle stress is updated within a step.
///
///   usf   update stress first: velocity gradient from the particle-to-grid velocities, stress
///         update, then internal forces (Bardenhagen's USF).
///   usl   update stress last: internal forces from the old stress, grid update, particle
///         update, then the velocity gradient from the updated grid velocities and the stress.
///   musl  modified USL (Sulsky): as usl, but the updated particle momenta are mapped back to the
///         grid and the velocity gradient comes from that remapped velocity (less noise, one
///         more grid pass).
/// Chosen by name through one registry; an unknown name is an error listing the valid ones.
#include <string>
#include <vector>

namespace mpmice::mpm {

enum class UpdateScheme { USF, USL, MUSL };

struct SchemeTraits {
  const char* name;
  UpdateScheme kind;
  bool stressFirst;     // stress update right after particle-to-grid
  bool remapVelocity;   // MUSL: particle velocities back to the grid before the stress update
  const char* brief;
};

const std::vector<SchemeTraits>& updateSchemes();
/// Name -> traits; throws std::invalid_argument listing the valid names.
const SchemeTraits& parseUpdateScheme(const std::string& name);

}  // namespace mpmice::mpm
