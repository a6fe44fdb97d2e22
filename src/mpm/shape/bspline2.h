#pragma once
/// @brief Quadratic B-spline shape functions: three nodes per direction, C1 weights.
///
/// Uniform node-centred splines, not modified at the mesh boundary: near a boundary they reach
/// the ghost node layer outside the mesh (the grid keeps one), which the boundary conditions
/// treat like the boundary node. Node-index units as in LinearShape.
#include "mpm/shape/floor_index.h"

namespace mpmice::mpm {

struct BSpline2Shape {
  static constexpr const char* kName = "bspline2";
  static constexpr int kNodes = 3;

  static inline void eval(double xi, double /*lp*/, int& base, double* w, double* dw) {
    base = floorIndex(xi - 0.5);
    const double fl = base;
    const double r0 = xi - fl;        // distance to node base, in [0.5, 1.5)
    const double r1 = r0 - 1.0;       // to base+1, in [-0.5, 0.5)
    const double r2 = r0 - 2.0;       // to base+2, in [-1.5, -0.5)
    const double t0 = 1.5 - r0, t2 = 1.5 + r2;
    w[0] = 0.5 * t0 * t0;
    w[1] = 0.75 - r1 * r1;
    w[2] = 0.5 * t2 * t2;
    dw[0] = -t0;
    dw[1] = -2.0 * r1;
    dw[2] = t2;
  }
};

}  // namespace mpmice::mpm
