#pragma once
/// @brief The FaceStencil as explicit matrix rows, with the boundary folded in the way the
/// pressure increment's ghost fill treats it (ice/boundary: FieldKind::Increment).
///
/// Across a periodic direction a neighbour is its periodic image (a coupling like any other).
/// Across any other side of the mesh the ghost is either a mirror of the boundary cell (zero
/// gradient: coef (x_c - x_ghost) = 0, the face drops out) or, where the side holds a fixed
/// pressure, zero (the increment vanishes there: coef x_c, the face's coefficient stays on the
/// diagonal and the right-hand side is unchanged). Shared by the assembled solvers (Eigen's
/// BiCGSTAB, hypre's structured PCG), so both see the matrix JacobiCg applies through the ghosts.
#include <array>

#include "ice/linear/linear_operator.h"

namespace mpmice::ice::linear {

/// The mesh's cells and how each of its sides closes the system; fixedSide[2 d + (0 low, 1 high)].
struct StencilBoundary {
  core::Box domain;
  std::array<bool, 3> periodic{false, false, false};
  std::array<bool, 6> fixedSide{};
};

/// row(i, j, k, diag, off) for every owned cell of A: diag the diagonal entry, off[2 d + (0 low,
/// 1 high)] the coefficient c >= 0 of the coupling -c x_neighbour (0 where the face has none:
/// a boundary face that is not periodic). The neighbour across a periodic side is the image.
template <class Row>
void forEachRow(const FaceStencil& A, const StencilBoundary& bc, Row&& row) {
  core::forEach(A.owned, [&](int i, int j, int k) {
    double diag = A.centre(i, j, k);
    std::array<double, 6> off{};
    for (int d = 0; d < A.dim; ++d)
      for (int s = 0; s < 2; ++s) {
        int nb[3] = {i, j, k}, f[3] = {i, j, k};
        nb[d] += s ? 1 : -1;
        f[d] += s;
        const double c = A.coef[d](f[0], f[1], f[2]);
        const bool outside = nb[d] < bc.domain.lo[d] || nb[d] > bc.domain.hi[d];
        if (outside && !bc.periodic[d]) {
          if (bc.fixedSide[2 * d + s]) diag += c;
          continue;
        }
        diag += c;
        off[2 * d + s] = c;
      }
    row(i, j, k, diag, off);
  });
}

}  // namespace mpmice::ice::linear
