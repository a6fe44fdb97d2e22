#include "ice/linear/linear_operator.h"

namespace mpmice::ice::linear {

using core::Field;
using core::forEach;

void FaceStencil::allocate(const core::Box& ownedBox, int dimension) {
  owned = ownedBox;
  dim = dimension;
  centre = Field("stencil_centre", core::Centering::Cell, owned, 1, 0);
  for (int d = 0; d < dim; ++d) coef[d] = Field("stencil_face", core::Centering::Cell, owned.faces(d), 1, 0);
}

void FaceStencil::apply(Field& x, Field& y) const {
  fillGhosts(x);
  forEach(owned, [&](int i, int j, int k) {
    const double xc = x(i, j, k);
    double acc = centre(i, j, k) * xc;
    for (int d = 0; d < dim; ++d) {
      int lo[3] = {i, j, k}, hi[3] = {i, j, k};
      lo[d] -= 1;
      hi[d] += 1;
      acc += coef[d](i, j, k) * (xc - x(lo[0], lo[1], lo[2]));
      acc += coef[d](hi[0], hi[1], hi[2]) * (xc - x(hi[0], hi[1], hi[2]));
    }
    y(i, j, k) = acc;
  });
}

void FaceStencil::diagonal(Field& dg) const {
  forEach(owned, [&](int i, int j, int k) {
    double s = centre(i, j, k);
    for (int d = 0; d < dim; ++d) {
      int hi[3] = {i, j, k};
      hi[d] += 1;
      s += coef[d](i, j, k) + coef[d](hi[0], hi[1], hi[2]);
    }
    dg(i, j, k) = s;
  });
}

}  // namespace mpmice::ice::linear
