#pragma once
/// @brief The cell-centred state of one solid material, what ICE receives in phase (1) of the
/// MPM-ICE step: mass, velocity, temperature, volume and specific volume per owned cell.
///
/// Node values come from a particle-to-grid pass of that material alone and go to cell centres
/// with equal weights per node; a node's share is divided among the mesh cells around it, so a
/// node on a mesh face (e.g. a symmetry plane) counts double and total mass is conserved.
#include "core/field/field.h"

namespace mpmice::mpm {

struct SolidCellState {
  core::Field mass;            // [kg] (per unit depth in 2D)
  core::Field velocity;        // 3 components [m/s]
  core::Field temperature;     // [K]
  core::Field volume;          // particle volume in the cell [m^3]
  core::Field specificVolume;  // volume / mass [m^3/kg], 0 in empty cells
};

}  // namespace mpmice::mpm
