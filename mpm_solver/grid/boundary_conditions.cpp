#include "grid/boundary_conditions.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace mpmice::mpm {

using core::BoundaryType;

namespace {
const char* const kFaceNames[6] = {"x-", "x+", "y-", "y+", "z-", "z+"};
}

BoundaryConditions::BoundaryConditions(const std::array<core::BoundarySpec, 6>& faces,
                                       const core::Mesh& mesh, const core::Box& nodeBox) {
  const int dim = mesh.dim();
  for (int f = 0; f < 2 * dim; ++f) {
    const int d = f / 2;
    const bool high = f % 2 == 1;
    const BoundaryType t = faces[f].type;
    if (t == BoundaryType::Periodic)
      throw std::invalid_argument(std::string("boundary.") + kFaceNames[f] +
                                  ": periodic boundaries are not supported by mpm_solver; use "
                                  "symmetry, slip_wall, noslip_wall or free");
    std::vector<int> comps;
    if (t == BoundaryType::NoSlipWall) {
      for (int c = 0; c < dim; ++c) comps.push_back(c);
    } else if (t == BoundaryType::Symmetry || t == BoundaryType::SlipWall) {
      comps.push_back(d);
    } else {
      continue;  // free, inflow, outflow
    }
    // Nodes on the face and beyond it.
    core::Box b = nodeBox;
    const int n = mesh.cells()[d];
    if (high)
      b.lo[d] = std::max(b.lo[d], n);
    else
      b.hi[d] = std::min(b.hi[d], 0);
    if (!b.ok()) continue;
    core::forEach(b, [&](int i, int j, int k) {
      for (int c : comps) {
        idx_.push_back(nodeBox.index(i, j, k));
        comp_.push_back(c);
      }
    });
  }
}

void BoundaryConditions::apply(core::Field& v) const {
  double* p[3] = {v.data(0), v.data(1), v.data(2)};
  for (std::size_t n = 0; n < idx_.size(); ++n) p[comp_[n]][idx_[n]] = 0.0;
}

}  // namespace mpmice::mpm
