#pragma once
/// @brief The number of materials and the mesh's dimension fixed at compile time for the cell
/// loops (their small loops unroll and take the lane paths; the same operations in the same
/// order as with the run-time counts), and the row sweep the lane paths share.
#include <cstdint>

#include "core/mesh/box.h"

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

/// The cells of `box` in forEach's order, by rows: with NM, DIM > 0 four cells of a row at a time
/// through lanes.template operator()<NM, DIM>(c, o) while four remain, the rest of the row (every
/// cell with the run-time counts <0, 0>) through one.template operator()<NM, DIM>(c, o); c the
/// cell's index in `stored`, o the number of box's cells before it (of type Index).
template <int NM, int DIM, class Index, class Lanes, class One>
inline void sweepRowsByLanes(const core::Box& box, const core::Box& stored, Lanes& lanes, One& one) {
  Index o = 0;
  for (int k = box.lo[2]; k <= box.hi[2]; ++k)
    for (int j = box.lo[1]; j <= box.hi[1]; ++j) {
      std::int64_t c = stored.index(box.lo[0], j, k);
      int i = box.lo[0];
      if constexpr (NM > 0 && DIM > 0)
        for (; i + 3 <= box.hi[0]; i += 4, c += 4, o += 4) lanes.template operator()<NM, DIM>(c, o);
      for (; i <= box.hi[0]; ++i, ++c, ++o) one.template operator()<NM, DIM>(c, o);
    }
}

}  // namespace mpmice::ice
