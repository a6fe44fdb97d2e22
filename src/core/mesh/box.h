#pragma once
/// @brief A rectangular range of integer indices, inclusive at both ends.
///
/// Boxes describe cell, node and face index ranges of the structured background mesh in 1D, 2D
/// and 3D. Unused directions have lo = hi = 0. A default-constructed Box is invalid (empty): test
/// with ok(). Algebra: intersect (&), grow/shrink by ghost layers, shift, conversion between cell
/// and node ranges. Linear indices run x fastest (i + nx (j + ny k)).
#include <array>
#include <cstdint>
#include <ostream>
#include <string>

namespace mpmice::core {

using IntVect = std::array<int, 3>;

struct Box {
  IntVect lo{0, 0, 0};
  IntVect hi{-1, -1, -1};

  Box() = default;
  Box(IntVect l, IntVect h) : lo(l), hi(h) {}

  /// True when the box holds at least one index.
  [[nodiscard]] bool ok() const { return hi[0] >= lo[0] && hi[1] >= lo[1] && hi[2] >= lo[2]; }
  [[nodiscard]] int length(int d) const { return ok() ? hi[d] - lo[d] + 1 : 0; }
  [[nodiscard]] std::int64_t numPts() const {
    return ok() ? std::int64_t(length(0)) * length(1) * length(2) : 0;
  }
  [[nodiscard]] bool contains(int i, int j, int k) const {
    return i >= lo[0] && i <= hi[0] && j >= lo[1] && j <= hi[1] && k >= lo[2] && k <= hi[2];
  }
  [[nodiscard]] bool contains(const Box& b) const {
    return !b.ok() || (ok() && contains(b.lo[0], b.lo[1], b.lo[2]) && contains(b.hi[0], b.hi[1], b.hi[2]));
  }
  /// Linear offset of (i,j,k) inside this box, x fastest. Meaningful for a valid box only (the
  /// lengths are taken without ok(): this runs once per cell in most loops).
  [[nodiscard]] std::int64_t index(int i, int j, int k) const {
    return (i - lo[0]) + std::int64_t(hi[0] - lo[0] + 1) * ((j - lo[1]) + std::int64_t(hi[1] - lo[1] + 1) * (k - lo[2]));
  }
  /// Grow by n in the first `dim` directions (negative n shrinks).
  [[nodiscard]] Box grow(int n, int dim = 3) const;
  /// Grow by n in direction d only.
  [[nodiscard]] Box growDir(int d, int n) const;
  [[nodiscard]] Box shrink(int n, int dim = 3) const { return grow(-n, dim); }
  [[nodiscard]] Box shift(const IntVect& s) const;
  /// The nodes that surround these cells (hi + 1 in the first `dim` directions).
  [[nodiscard]] Box surroundingNodes(int dim) const;
  /// The faces normal to direction d that bound these cells (hi + 1 in d).
  [[nodiscard]] Box faces(int d) const { return growHi(d, 1); }
  [[nodiscard]] Box growHi(int d, int n) const;
  [[nodiscard]] Box growLo(int d, int n) const;
  [[nodiscard]] std::string str() const;

  friend bool operator==(const Box& a, const Box& b) {
    return (!a.ok() && !b.ok()) || (a.lo == b.lo && a.hi == b.hi);
  }
};

/// Intersection; invalid when the boxes do not overlap.
Box operator&(const Box& a, const Box& b);
std::ostream& operator<<(std::ostream& os, const Box& b);

/// Calls f(i, j, k) for every index of the box, x fastest.
template <class F>
inline void forEach(const Box& b, F&& f) {
  for (int k = b.lo[2]; k <= b.hi[2]; ++k)
    for (int j = b.lo[1]; j <= b.hi[1]; ++j)
      for (int i = b.lo[0]; i <= b.hi[0]; ++i) f(i, j, k);
}

}  // namespace mpmice::core
