#include "mpm/grid/boundary_conditions.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace mpmice::mpm {

using core::BoundaryType;

namespace {
const char* const kFaceNames[6] = {"x-", "x+", "y-", "y+", "z-", "z+"};
}

BoundaryConditions::BoundaryConditions(const std::array<core::BoundarySpec, 6>& faces,
                                       const core::Mesh& mesh, const core::Box& nodeBox)
    : npts_(nodeBox.numPts()) {
  const int dim = mesh.dim();
  for (int f = 0; f < 2 * dim; ++f) {
    const BoundaryType t = faces[f].type;
    if (t == BoundaryType::Periodic)
      throw std::invalid_argument(std::string("boundary.") + kFaceNames[f] +
                                  ": periodic boundaries are not supported by mpm_solver; use "
                                  "symmetry, slip_wall, noslip_wall or free");
  }
  for (int f = 0; f < 2 * dim; ++f) {
    const int d = f / 2;
    const bool high = f % 2 == 1;
    const BoundaryType t = faces[f].type;
    const bool mirrorFace = t == BoundaryType::Symmetry || t == BoundaryType::SlipWall;
    std::vector<int> comps;
    if (t == BoundaryType::NoSlipWall) {
      for (int c = 0; c < dim; ++c) comps.push_back(c);
    } else if (mirrorFace) {
      comps.push_back(d);
    } else {
      continue;  // free, inflow, outflow
    }
    const int n = mesh.cells()[d];
    // Constrained nodes: on the face (mirror planes), on the face and beyond it (walls).
    core::Box b = nodeBox;
    if (high) {
      b.lo[d] = std::max(b.lo[d], n);
      if (mirrorFace) b.hi[d] = std::min(b.hi[d], n);
    } else {
      b.hi[d] = std::min(b.hi[d], 0);
      if (mirrorFace) b.lo[d] = std::max(b.lo[d], 0);
    }
    if (b.ok())
      core::forEach(b, [&](int i, int j, int k) {
        for (int c : comps) {
          idx_.push_back(nodeBox.index(i, j, k));
          comp_.push_back(c);
        }
      });
    if (!mirrorFace) continue;
    // Ghost nodes strictly beyond the plane and their mirror nodes inside.
    core::Box g = nodeBox;
    if (high)
      g.lo[d] = std::max(g.lo[d], n + 1);
    else
      g.hi[d] = std::min(g.hi[d], -1);
    if (!g.ok()) continue;
    MirrorFace mf{d, {}};
    core::forEach(g, [&](int i, int j, int k) {
      int m[3] = {i, j, k};
      m[d] = high ? 2 * n - m[d] : -m[d];
      if (!nodeBox.contains(m[0], m[1], m[2]))
        throw std::logic_error("BoundaryConditions: the mirror of a ghost node beyond boundary." +
                               std::string(kFaceNames[f]) + " is not stored on this rank");
      mf.pairs.emplace_back(nodeBox.index(i, j, k), nodeBox.index(m[0], m[1], m[2]));
    });
    mirrors_.push_back(std::move(mf));
  }
  // Direction order (x, y, z) for edges and corners; faces were visited in that order already.
  std::stable_sort(mirrors_.begin(), mirrors_.end(),
                   [](const MirrorFace& a, const MirrorFace& b) { return a.dir < b.dir; });
}

void BoundaryConditions::apply(core::Field& v) const {
  const auto p = components(v);
  for (std::size_t n = 0; n < idx_.size(); ++n) p[comp_[n]][idx_[n]] = 0.0;
  mirror(v, Parity::Vector);
}

template <class Op>
void BoundaryConditions::forMirrorPairs(core::Field& f, Parity parity, const char* who, Op&& op) const {
  if (mirrors_.empty()) return;
  if (f.npts() != npts_)
    throw std::logic_error(std::string("BoundaryConditions::") + who + ": field '" + f.name() +
                           "' is not on the node box");
  for (const MirrorFace& mf : mirrors_)
    for (int c = 0; c < f.ncomp(); ++c) {
      double* a = f.data(c);
      const double s = parity == Parity::Vector && c == mf.dir ? -1.0 : 1.0;
      for (const auto& [gh, mi] : mf.pairs) op(a, gh, mi, s);
    }
}

void BoundaryConditions::fold(core::Field& f, Parity parity) const {
  forMirrorPairs(f, parity, "fold", [](double* a, std::int64_t gh, std::int64_t mi, double s) {
    a[mi] += s * a[gh];
    a[gh] = 0.0;
  });
}

void BoundaryConditions::mirror(core::Field& f, Parity parity) const {
  forMirrorPairs(f, parity, "mirror", [](double* a, std::int64_t gh, std::int64_t mi, double s) { a[gh] = s * a[mi]; });
}

}  // namespace mpmice::mpm
