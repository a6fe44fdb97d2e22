#pragma once
/// @brief Cubic B-spline shape functions: four nodes per direction, C2 weights.
///
/// Uniform node-centred splines, not modified at the mesh boundary (see BSpline2Shape). The
/// widest stencil: most accurate on smooth fields, 16 (2D) or 64 (3D) nodes per particle.
#include "mpm/shape/floor_index.h"

namespace mpmice::mpm {

struct BSpline3Shape {
  static constexpr const char* kName = "bspline3";
  static constexpr int kNodes = 4;

  static inline void eval(double xi, double /*lp*/, int& base, double* w, double* dw) {
    const int i = floorIndex(xi);
    base = i - 1;
    const double fl = i;
    const double f = xi - fl;  // in [0, 1)
    // Distances to nodes base..base+3: 1+f, f, 1-f, 2-f.
    const double a0 = 1.0 + f, a1 = f, a2 = 1.0 - f, a3 = 2.0 - f;
    const double t0 = 2.0 - a0, t3 = 2.0 - a3;
    w[0] = t0 * t0 * t0 / 6.0;
    w[1] = 0.5 * a1 * a1 * a1 - a1 * a1 + 2.0 / 3.0;
    w[2] = 0.5 * a2 * a2 * a2 - a2 * a2 + 2.0 / 3.0;
    w[3] = t3 * t3 * t3 / 6.0;
    dw[0] = -0.5 * t0 * t0;
    dw[1] = 1.5 * a1 * a1 - 2.0 * a1;
    dw[2] = -(1.5 * a2 * a2 - 2.0 * a2);
    dw[3] = 0.5 * t3 * t3;
  }
};

}  // namespace mpmice::mpm
