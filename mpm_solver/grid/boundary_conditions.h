#pragma once
/// @brief Velocity boundary conditions on the grid's mesh faces.
///
/// Per face of the scene's `boundary`: noslip_wall = fixed (every velocity component 0);
/// symmetry and slip_wall = roller (the normal component 0); free, outflow and inflow = free
/// (nothing). They act on the nodes on the face and on the ghost nodes beyond it (which the wider
/// stencils reach). periodic is not supported by the MPM solver yet and is an error.
#include <array>
#include <cstdint>
#include <vector>

#include "grid/grid.h"
#include "scene/scene.h"

namespace mpmice::mpm {

class BoundaryConditions {
 public:
  BoundaryConditions() = default;
  BoundaryConditions(const std::array<core::BoundarySpec, 6>& faces, const core::Mesh& mesh,
                     const core::Box& nodeBox);
  /// Zeroes the constrained components of a three-component node field.
  void apply(core::Field& v) const;
  [[nodiscard]] std::size_t numConstraints() const { return idx_.size(); }

 private:
  std::vector<std::int64_t> idx_;  // node offset in the field
  std::vector<int> comp_;          // component to zero
};

}  // namespace mpmice::mpm
