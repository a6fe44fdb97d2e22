#pragma once
/// @brief Four faces (or cells) of a row as the lanes of one vector: GCC vector extensions (AVX
/// registers where the build has them, SSE2 pairs on the baseline). Every lane-wise operation is
/// the scalar one, and a branch of the scalar code becomes a select of the value it would have
/// kept (sel), so lane-wise code gives the scalar code's bits; what it gains is the divisions and
/// square roots of four faces in one instruction.
#include <cmath>
#include <cstdint>
#include <cstring>

#ifdef __AVX__
#include <immintrin.h>
#endif

// The vectors pass by value between inline functions: a build without AVX (MPMICE_SIMD baseline)
// warns that a 32-byte vector's ABI differs from an AVX build's (-Wpsabi; only calls between
// objects built with different flags would care, and there are none). Off for the rest of every
// file that includes this one: GCC issues it where it emits the function, which can be after a
// diagnostic pop (a push / pop pair here still fails a baseline -Werror build).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace mpmice::ice::lanes {

using v4d = double __attribute__((vector_size(32)));
/// Lane masks, as comparisons of v4d give them: -1 (true) or 0.
using v4m = std::int64_t __attribute__((vector_size(32)));

inline v4d load(const double* p) {
  v4d v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline void store(double* p, v4d v) { std::memcpy(p, &v, sizeof v); }
/// m ? a : b lane by lane.
inline v4d sel(v4m m, v4d a, v4d b) { return m ? a : b; }
inline v4d splat(double x) { return v4d{x, x, x, x}; }
/// |v| lane by lane (std::abs: the sign bit cleared).
inline v4d abs(v4d v) {
  using v4u = std::uint64_t __attribute__((vector_size(32)));
  v4u b;
  std::memcpy(&b, &v, sizeof b);
  b &= ~(std::uint64_t{1} << 63);
  std::memcpy(&v, &b, sizeof v);
  return v;
}
/// The square root lane by lane (correctly rounded, as std::sqrt).
inline v4d sqrt(v4d v) {
#ifdef __AVX__
  return v4d(_mm256_sqrt_pd(__m256d(v)));
#else
  return v4d{std::sqrt(v[0]), std::sqrt(v[1]), std::sqrt(v[2]), std::sqrt(v[3])};
#endif
}
/// Whether any lane of m is set.
inline bool any(v4m m) { return (m[0] | m[1] | m[2] | m[3]) != 0; }

}  // namespace mpmice::ice::lanes
