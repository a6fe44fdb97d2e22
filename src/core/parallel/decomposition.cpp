#include "core/parallel/decomposition.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace mpmice::core {

IntVect chooseProcessGrid(const IntVect& cells, int dim, int nranks) {
  IntVect best{nranks, 1, 1};
  double bestCost = std::numeric_limits<double>::max();
  for (int px = 1; px <= nranks; ++px) {
    if (nranks % px) continue;
    for (int py = 1; py <= nranks / px; ++py) {
      if ((nranks / px) % py) continue;
      const int pz = nranks / px / py;
      IntVect p{px, py, pz};
      bool fits = true;
      for (int d = 0; d < 3; ++d)
        if ((d >= dim && p[d] != 1) || p[d] > cells[d]) fits = false;
      if (!fits) continue;
      // Total cut surface: (p_d - 1) cut planes of the mesh's cross-section normal to d.
      double cost = 0;
      for (int d = 0; d < dim; ++d) {
        double area = 1;
        for (int e = 0; e < dim; ++e)
          if (e != d) area *= cells[e];
        cost += (p[d] - 1) * area;
      }
      if (cost < bestCost - 1e-12) {
        bestCost = cost;
        best = p;
      }
    }
  }
  if (bestCost == std::numeric_limits<double>::max())
    throw std::invalid_argument("Decomposition: " + std::to_string(nranks) +
                                " ranks cannot each own at least one cell of this mesh");
  return best;
}

Decomposition::Decomposition(const Mesh& mesh, int nranks, std::array<bool, 3> periodic)
    : mesh_(mesh), periodic_(periodic) {
  if (nranks < 1) throw std::invalid_argument("Decomposition: need at least one rank");
  for (int d = mesh.dim(); d < 3; ++d) periodic_[d] = false;
  pgrid_ = chooseProcessGrid(mesh.cells(), mesh.dim(), nranks);
  for (int d = 0; d < 3; ++d) {
    const int n = mesh.cells()[d], p = pgrid_[d];
    cuts_[d].resize(p + 1);
    for (int q = 0; q <= p; ++q) cuts_[d][q] = static_cast<int>((static_cast<long long>(n) * q) / p);
  }
  cellBoxes_.resize(nranks);
  for (int r = 0; r < nranks; ++r) {
    const int q[3] = {r % pgrid_[0], (r / pgrid_[0]) % pgrid_[1], r / (pgrid_[0] * pgrid_[1])};
    Box b;
    for (int d = 0; d < 3; ++d) {
      b.lo[d] = cuts_[d][q[d]];
      b.hi[d] = cuts_[d][q[d] + 1] - 1;
    }
    cellBoxes_[r] = b;
  }
}

IntVect Decomposition::period(Centering c) const {
  IntVect p = mesh_.cells();
  if (c == Centering::Node)
    for (int d = 0; d < mesh_.dim(); ++d)
      if (!periodic_[d]) p[d] += 1;
  return p;
}

Box Decomposition::domainBox(Centering c) const {
  return c == Centering::Cell ? mesh_.cellBox() : mesh_.nodeBox();
}

Box Decomposition::ownedBox(int r, Centering c) const {
  Box b = cellBoxes_[r];
  if (c == Centering::Node)
    for (int d = 0; d < mesh_.dim(); ++d)
      if (!periodic_[d] && b.hi[d] == mesh_.cells()[d] - 1) b.hi[d] += 1;
  return b;
}

Box Decomposition::storedBox(int r, Centering c, int ng) const {
  Box b = cellBoxes_[r];
  if (c == Centering::Node) b = b.surroundingNodes(mesh_.dim());
  return b.grow(ng, mesh_.dim());
}

int Decomposition::ownerOfCell(int i, int j, int k) const {
  const int idx[3] = {i, j, k};
  int q[3];
  for (int d = 0; d < 3; ++d) {
    if (idx[d] < 0 || idx[d] >= mesh_.cells()[d]) return -1;
    const auto& c = cuts_[d];
    q[d] = static_cast<int>(std::upper_bound(c.begin(), c.end(), idx[d]) - c.begin()) - 1;
  }
  return q[0] + pgrid_[0] * (q[1] + pgrid_[1] * q[2]);
}

}  // namespace mpmice::core
