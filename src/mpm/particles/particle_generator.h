#pragma once
/// @brief Material points from the scene's geometry objects.
///
/// Every geometry object whose fill names a solid material seeds particles_per_cell[d] points
/// per direction in each cell (at the centres of the cell's sub-cells) that its shape contains;
/// where solid objects overlap, the later one wins. A rank seeds only the cells it owns, and ids
/// come from the cell index, so the set of particles does not depend on the number of ranks.
/// Each particle carries volume = cell volume / points per cell, mass = density x volume, the
/// object's velocity and temperature, and half its spacing per direction (GIMP's half-width).
/// Errors: a solid object reaching outside the mesh (except across symmetry faces), density <= 0.
#include <functional>

#include "mpm/particles/particle_set.h"
#include "core/scene/scene.h"

namespace mpmice::mpm {

/// Membership test of a shape (default: ShapeSpec::contains).
using ContainsFn = std::function<bool(const core::ShapeSpec&, const core::RealVect&, int dim)>;

/// Appends the particles of the cells in `cells` (owned cells of this rank) to `out`.
void generateParticles(const core::Scene& scene, const core::Box& cells, ParticleSet& out,
                       const ContainsFn& contains);

}  // namespace mpmice::mpm
