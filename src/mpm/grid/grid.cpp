#include "mpm/grid/grid.h"

namespace mpmice::mpm {

using core::Centering;
using core::Field;

Grid::Grid(const core::Decomposition& decomp, const core::Comm& comm, bool exteriorGhosts)
    : exchange_(decomp, comm, Centering::Node, kGhost, exteriorGhosts), serial_(comm.size() == 1) {
  const core::Box b = decomp.storedBox(comm.rank(), Centering::Node, kGhost);
  mass = Field("mass", Centering::Node, b, 1, kGhost);
  const int nv = decomp.mesh().dim();  // vector components: the mesh's directions
  velocity = Field("velocity", Centering::Node, b, nv, kGhost);
  velocityL = Field("velocityL", Centering::Node, b, nv, kGhost);
  force = Field("force", Centering::Node, b, nv, kGhost);
  externalForce = Field("externalForce", Centering::Node, b, nv, kGhost);
  externalWork = Field("externalWork", Centering::Node, b, 1, kGhost);
  geom_.lo = b.lo;
  geom_.sy = b.length(0);
  geom_.sz = std::int64_t(b.length(0)) * b.length(1);
  const auto& m = decomp.mesh();
  for (int d = 0; d < 3; ++d) {
    geom_.origin[d] = m.origin()[d];
    geom_.invDx[d] = 1.0 / m.dx(d);
  }
  // Periodic directions are rejected by the solver, so one rank needs no exchange at all.
}

void Grid::ensureRemap() {
  if (remap.npts() == 0) remap = Field("remap", Centering::Node, mass.box(), velocity.ncomp(), kGhost);
}

void Grid::sumAndFill(const std::vector<core::Field*>& fs) const {
  if (!serial_) exchange_.sumAndFill(fs);
}

void Grid::fill(const std::vector<core::Field*>& fs) const {
  if (!serial_) exchange_.fill(fs);
}

}  // namespace mpmice::mpm
