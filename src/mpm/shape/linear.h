#pragma once
/// @brief Linear hat shape functions (the paper's, Sulsky's MPM): two nodes per direction.
///
/// Evaluated in node-index units: xi = (x - origin) / dx, so node i sits at xi = i. eval() gives
/// the first node of the stencil and, per stencil node, the weight and its derivative d/dxi
/// (divide by dx for the physical gradient). C0 across cell faces: particles crossing cells
/// feel the jump of the gradient (cell-crossing noise).
#include "mpm/shape/floor_index.h"

namespace mpmice::mpm {

struct LinearShape {
  static constexpr const char* kName = "linear";
  static constexpr int kNodes = 2;

  static inline void eval(double xi, double /*lp*/, int& base, double* w, double* dw) {
    base = floorIndex(xi);
    const double fl = base;
    const double f = xi - fl;
    w[0] = 1.0 - f;
    w[1] = f;
    dw[0] = -1.0;
    dw[1] = 1.0;
  }
};

}  // namespace mpmice::mpm
