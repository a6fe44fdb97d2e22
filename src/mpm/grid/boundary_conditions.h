#pragma once
/// @brief Velocity boundary conditions on the grid's mesh faces, and the mirror images at
/// symmetry planes.
///
/// Per face of the scene's `boundary`: noslip_wall = fixed (every velocity component 0 on the
/// face nodes and on the ghost nodes beyond it); symmetry and slip_wall = mirror (reflection):
/// the face nodes keep a zero normal component and the ghost nodes beyond the plane are the mirror
/// images of the nodes inside (node -g <-> g at a low face, n + g <-> n - g at a high one; normal
/// component of vectors negated); free, outflow and inflow = free (nothing). periodic is not
/// supported by the MPM solver yet and is an error.
///
/// Mirror planes in the two particle-to-grid directions (the wide stencils, B-splines and GIMP
/// near a face, reach the ghost layer):
///  - fold(): what the particles deposited on a ghost node beyond a mirror plane is added to its
///    mirror node inside (normal component of vectors with its sign flipped) and the ghost is
///    cleared: exactly the contribution of the mirror particles beyond the plane. The face nodes
///    are left alone (their mirror is themselves; values per unit mass are unchanged either way).
///  - mirror(): ghost nodes take the mirror node's values (after the ghost sum), for the
///    grid-to-particle interpolation and the gradients.
/// Faces are processed in direction order (x, y, z) in both, which makes edges and corners (ghost
/// in several directions) fold onto and mirror from the right interior node. fold() is linear and
/// every rank that stores a ghost node beyond a face also stores its mirror node (a rank has at
/// least one cell and one ghost layer), so each rank folds its own partial sums before the ghost
/// sum and mirrors after it: no extra communication, same totals as folding on the owner.
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "mpm/grid/grid.h"
#include "core/scene/scene.h"

namespace mpmice::mpm {

/// How a node field behaves under reflection: scalars (mass, volume, m T) are even; vectors
/// (momentum, velocity, force) flip the component normal to the plane.
enum class Parity { Scalar, Vector };

class BoundaryConditions {
 public:
  BoundaryConditions() = default;
  BoundaryConditions(const std::array<core::BoundarySpec, 6>& faces, const core::Mesh& mesh,
                     const core::Box& nodeBox);
  /// Velocity conditions on a three-component node velocity: zeroes the constrained components,
  /// then fills the ghost nodes beyond mirror planes with the mirror images.
  void apply(core::Field& v) const;
  /// Folds particle contributions on ghost nodes beyond mirror planes onto their mirror nodes.
  void fold(core::Field& f, Parity parity) const;
  /// Ghost nodes beyond mirror planes take their mirror node's values.
  void mirror(core::Field& f, Parity parity) const;
  [[nodiscard]] std::size_t numConstraints() const { return idx_.size(); }
  [[nodiscard]] bool hasMirrors() const { return !mirrors_.empty(); }

 private:
  std::vector<std::int64_t> idx_;  // node offset in the field
  std::vector<int> comp_;          // component to zero
  struct MirrorFace {
    int dir;                                                 // normal direction
    std::vector<std::pair<std::int64_t, std::int64_t>> pairs;  // (ghost, mirror) node offsets
  };
  std::vector<MirrorFace> mirrors_;  // in direction order
  /// Calls op(component data, ghost, mirror, sign) for every mirror pair and component of f (a
  /// node-box field; `who` names the caller in the error otherwise).
  template <class Op>
  void forMirrorPairs(core::Field& f, Parity parity, const char* who, Op&& op) const;
  std::int64_t npts_ = 0;            // points of the node box (checked against the fields)
};

}  // namespace mpmice::mpm
