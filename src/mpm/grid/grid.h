#pragma once
/// @brief The background grid of one rank: node fields over the rank's nodes plus one ghost
/// layer, and their exchange with neighbouring ranks.
///
/// Node fields (core::Field; vectors with the mesh's dimension of components: 2D nodes hold no z
/// component, which was an exact zero; components() gives null beyond them): mass,
/// velocity (particle-to-grid velocity v_n), velocityL (Lagrangian velocity after the grid
/// update), force (internal + body + loads), externalForce (the coupler's hook: e.g. ICE's
/// pressure force, added in the grid update), externalWork (the work that force did) and remap (MUSL's remapped velocity,
/// the coupling's scratch; made on first use: ensureRemap). The ghost
/// layer reaches one node beyond the mesh at its faces, so B-splines need no special stencil; with
/// `exteriorGhosts` (the B-spline shapes) that exterior layer belongs to the rank at the face and
/// is summed across ranks like any owned node (GhostExchange's ownExterior).
#include <array>
#include <vector>

#include "core/field/components.h"
#include "core/field/field.h"
#include "core/mesh/mesh.h"
#include "core/parallel/comm.h"
#include "core/parallel/decomposition.h"
#include "core/parallel/ghost_exchange.h"

namespace mpmice::mpm {

/// Flat addressing of the node fields for the hot loops.
struct GridGeom {
  core::IntVect lo{0, 0, 0};
  std::int64_t sy = 0, sz = 0;
  double origin[3] = {0, 0, 0};
  double invDx[3] = {1, 1, 1};
  [[nodiscard]] std::int64_t index(int i, int j, int k) const {
    return (i - lo[0]) + sy * (j - lo[1]) + sz * (k - lo[2]);
  }
};

/// The component arrays of a node vector field for the hot loops: core::components (null beyond
/// the mesh's dimension).
using core::components;

class Grid {
 public:
  static constexpr int kGhost = 1;
  Grid(const core::Decomposition& decomp, const core::Comm& comm, bool exteriorGhosts = false);

  [[nodiscard]] const core::Box& box() const { return mass.box(); }
  [[nodiscard]] const GridGeom& geom() const { return geom_; }
  [[nodiscard]] std::int64_t numNodes() const { return mass.npts(); }
  /// Adds ghost contributions into owners and copies totals back (no-op on one rank).
  void sumAndFill(const std::vector<core::Field*>& fs) const;
  /// Owners' values into ghosts (no-op on one rank).
  void fill(const std::vector<core::Field*>& fs) const;

  /// Allocates remap on first use (MUSL's velocity remap and the coupling's node-cell operators;
  /// an uncoupled USL / USF run never holds it).
  void ensureRemap();

  core::Field mass, velocity, velocityL, force, externalForce, remap;
  /// Work of externalForce in this step's grid update [J]: dt f_ext . (v_n + v_L) / 2 where the
  /// node accelerates (exactly the kinetic energy the coupling forces gave the node).
  core::Field externalWork;

 private:
  GridGeom geom_;
  core::GhostExchange exchange_;
  bool serial_;
};

}  // namespace mpmice::mpm
