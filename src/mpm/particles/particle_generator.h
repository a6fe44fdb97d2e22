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
#include <string>
#include <vector>

#include "mpm/particles/particle_set.h"
#include "core/scene/scene.h"

namespace mpmice::mpm {

/// Membership test of a shape (default: ShapeSpec::contains).
using ContainsFn = std::function<bool(const core::ShapeSpec&, const core::RealVect&, int dim)>;

/// What a solid geometry object asked for against what its particles fill (this rank's cells;
/// sums over ranks add): the particles' volume, and the shape's volume inside the mesh (less
/// what a later solid object claims), measured by sampling the cells the particle lattice does not
/// fill whole (kShapeVolumeSamples points per particle spacing and direction). A face of a shape
/// between two particle centres rounds to the nearer one: a box face half a spacing off the
/// lattice moves by up to half a spacing (docs/mpm.md "Geometry: what the particles fill").
struct RegionVolume {
  double particles = 0;  ///< sum of the particles' volumes [m^dim]
  double shape = 0;      ///< the shape's volume inside the mesh [m^dim]
};

/// Appends the particles of the cells in `cells` (owned cells of this rank) to `out`. With
/// `volumes`, also fills it per geometry object (index as scene.geometry; 0 for fluid objects).
void generateParticles(const core::Scene& scene, const core::Box& cells, ParticleSet& out,
                       const ContainsFn& contains, std::vector<RegionVolume>* volumes = nullptr);

/// One message per solid geometry object whose particles' volume differs from its shape's by more
/// than `tolerance` (relative; summed volumes over every rank), naming the object, both volumes,
/// the particle spacing and what to change. Empty when every object is represented within it.
std::vector<std::string> geometryVolumeWarnings(const core::Scene& scene, const std::vector<RegionVolume>& volumes,
                                                double tolerance);

}  // namespace mpmice::mpm
