#pragma once
/// @brief The owned cells' linear indices in the stored box (owned box grown by the ghosts), in
/// forEach's order, computed where they are read: a list of them held one int64 per cell, as much
/// as a field. Owned index a (0 .. size() - 1) is the a-th owned cell in that order.
#include <cstddef>
#include <cstdint>

#include "core/mesh/box.h"

namespace mpmice::ice {

class OwnedCells {
 public:
  OwnedCells() = default;
  OwnedCells(const core::Box& owned, const core::Box& stored) : owned_(owned), stored_(stored) {}

  [[nodiscard]] std::size_t size() const { return static_cast<std::size_t>(owned_.numPts()); }

  /// The stored index of owned cell a.
  [[nodiscard]] std::int64_t operator[](std::size_t a) const {
    const std::int64_t nx = owned_.length(0), ny = owned_.length(1), q = static_cast<std::int64_t>(a);
    return stored_.index(owned_.lo[0] + static_cast<int>(q % nx), owned_.lo[1] + static_cast<int>((q / nx) % ny),
                         owned_.lo[2] + static_cast<int>(q / (nx * ny)));
  }

  /// out[0 .. n - 1]: the stored indices of owned cells first .. first + n - 1 (one division for
  /// the first, then along the rows).
  void fill(std::size_t first, std::size_t n, std::int64_t* out) const {
    if (n == 0) return;
    const int nx = owned_.length(0);
    std::int64_t c = (*this)[first];
    int i = static_cast<int>(static_cast<std::int64_t>(first) % nx);
    for (std::size_t a = 0; a < n; ++a) {
      out[a] = c;
      if (++i < nx) {
        ++c;
      } else if (a + 1 < n) {
        i = 0;
        c = (*this)[first + a + 1];  // the next row (or plane)
      }
    }
  }

  /// f(a, c) for every owned cell in order (owned index a, stored index c), by rows.
  template <class F>
  void forEach(F&& f) const {
    std::size_t a = 0;
    for (int k = owned_.lo[2]; k <= owned_.hi[2]; ++k)
      for (int j = owned_.lo[1]; j <= owned_.hi[1]; ++j) {
        std::int64_t c = stored_.index(owned_.lo[0], j, k);
        for (int i = owned_.lo[0]; i <= owned_.hi[0]; ++i, ++a, ++c) f(a, c);
      }
  }

 private:
  core::Box owned_, stored_;
};

}  // namespace mpmice::ice
