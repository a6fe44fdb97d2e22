#pragma once
/// @brief uGIMP shape functions (Bardenhagen & Kober): the hat convolved with the particle's
/// characteristic function of half-width lp (fixed at its initial value, "undeformed" GIMP).
///
/// Three nodes per direction when lp <= dx/2 (particles-per-cell >= 1). Weights are C1 across
/// cell faces, which removes most of the cell-crossing noise of linear hats. Units: node-index
/// units as in LinearShape; lp in the same units.
#include <cmath>

#include "mpm/shape/floor_index.h"

namespace mpmice::mpm {

struct GimpShape {
  static constexpr const char* kName = "gimp";
  static constexpr int kNodes = 3;

  /// Weight and d/dxi of one node at signed distance r = xi - node (index units), half-width lp.
  static inline void node(double r, double lp, double& w, double& dw) {
    const double a = std::fabs(r);
    const double s = r < 0 ? -1.0 : 1.0;
    if (a < lp) {
      w = 1.0 - (r * r + lp * lp) / (2.0 * lp);
      dw = -r / lp;
    } else if (a <= 1.0 - lp) {
      w = 1.0 - a;
      dw = -s;
    } else if (a < 1.0 + lp) {
      const double t = 1.0 + lp - a;
      w = t * t / (4.0 * lp);
      dw = -s * t / (2.0 * lp);
    } else {
      w = 0.0;
      dw = 0.0;
    }
  }

  static inline void eval(double xi, double lp, int& base, double* w, double* dw) {
    base = floorIndex(xi - 0.5);
    for (int a = 0; a < 3; ++a) node(xi - (base + a), lp, w[a], dw[a]);
  }
};

}  // namespace mpmice::mpm
