#pragma once
/// @brief The number of materials and the mesh's dimension fixed at compile time for the cell
/// loops (their small loops unroll and take the lane paths; the same operations in the same
/// order as with the run-time counts).

namespace mpmice::ice {

/// Calls f.template operator()<NM, DIM>() with nm and dim as template arguments for 2 or 3
/// materials in 2D or 3D (and, with One, one material in 1D, 2D or 3D), <0, 0> otherwise (the
/// loops then read the run-time counts).
template <bool One, class F>
inline void withFixedCounts(int nm, int dim, F&& f) {
  if constexpr (One) {
    if (nm == 1 && dim == 1) return f.template operator()<1, 1>();
    if (nm == 1 && dim == 2) return f.template operator()<1, 2>();
    if (nm == 1 && dim == 3) return f.template operator()<1, 3>();
  }
  if (nm == 2 && dim == 2) f.template operator()<2, 2>();
  else if (nm == 2 && dim == 3) f.template operator()<2, 3>();
  else if (nm == 3 && dim == 2) f.template operator()<3, 2>();
  else if (nm == 3 && dim == 3) f.template operator()<3, 3>();
  else f.template operator()<0, 0>();
}

}  // namespace mpmice::ice
