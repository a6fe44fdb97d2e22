#pragma once
/// @brief The cell-centred state of one solid material, what ICE receives in phase (1) of the
/// MPM-ICE step: mass, velocity, temperature, volume and specific volume per owned cell.
///
/// Node values come from a particle-to-grid pass of that material alone and go to cell centres
/// with equal weights per node; a node's share is divided among the mesh cells around it, so a
/// node on a mesh face (e.g. a symmetry plane) counts double and total mass is conserved.
/// A cell the solid does not reach (mass at or below the mass floor) holds the absent-solid state:
/// mass 0, velocity 0, the reference specific volume 1 / rho0 and, where no temperature was
/// deposited, kReferenceTemperature (mpm/mpm_constants.h).
#include <cstdint>

#include "core/field/field.h"

namespace mpmice::mpm {

struct SolidCellState {
  core::Field mass;            // [kg] (per unit depth in 2D)
  core::Field velocity;        // 3 components [m/s]
  core::Field temperature;     // [K]
  core::Field volume;          // particle volume in the cell [m^3]
  core::Field specificVolume;  // volume / mass [m^3/kg]; 1 / rho0 in cells without solid
  /// The step generation (NodeCellOperators::generation()) this state was computed in.
  std::uint64_t stamp = 0;
};

}  // namespace mpmice::mpm
