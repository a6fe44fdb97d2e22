#include "mpm/material/signal_speed.h"

#include <algorithm>
#include <cmath>

namespace mpmice::mpm {

namespace {

/// out[k] = sqrt(M / (m / V)) + |v| for the n particles from the pointers, M = modulus, or with
/// kDense the particle's own: mDense where V <= denseRatio V0 (a crushable foam compacted to its
/// solid): a loop the compiler vectorizes (distinct arrays: restrict parameters; the choice is a
/// blend). Built for AVX2 as well as the x86-64 baseline and chosen at load time (target_clones):
/// the divisions and square roots are its cost and twice as many go per instruction; without FMA
/// (not part of the avx2 target) the operations and their bits are those of the baseline build.
template <int kDim, bool kDense>
void speeds(const double* __restrict__ mass, const double* __restrict__ vol, const double* __restrict__ vol0,
            const double* __restrict__ v0, const double* __restrict__ v1, const double* __restrict__ v2,
            double modulus, double mDense, double denseRatio, double* __restrict__ out, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k) {
    double vv = v0[k] * v0[k];
    if constexpr (kDim >= 2) vv += v1[k] * v1[k];
    if constexpr (kDim >= 3) vv += v2[k] * v2[k];
    double M = modulus;
    if constexpr (kDense) M = vol[k] <= denseRatio * vol0[k] ? mDense : modulus;
    out[k] = std::sqrt(M / (mass[k] / vol[k])) + std::sqrt(vv);
  }
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define MPMICE_SPEED_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define MPMICE_SPEED_CLONES
#endif

template <bool kDense>
void chunkSpeedsOf(int dim, const double* mass, const double* vol, const double* vol0, const double* v0,
                   const double* v1, const double* v2, double modulus, double mDense, double denseRatio, double* out,
                   std::size_t n) {
  if (dim == 1)
    speeds<1, kDense>(mass, vol, vol0, v0, v1, v2, modulus, mDense, denseRatio, out, n);
  else if (dim == 2)
    speeds<2, kDense>(mass, vol, vol0, v0, v1, v2, modulus, mDense, denseRatio, out, n);
  else
    speeds<3, kDense>(mass, vol, vol0, v0, v1, v2, modulus, mDense, denseRatio, out, n);
}

MPMICE_SPEED_CLONES
void chunkSpeeds(int dim, const double* mass, const double* vol, const double* vol0, const double* v0,
                 const double* v1, const double* v2, double modulus, double mDense, double denseRatio, double* out,
                 std::size_t n) {
  if (vol0)
    chunkSpeedsOf<true>(dim, mass, vol, vol0, v0, v1, v2, modulus, mDense, denseRatio, out, n);
  else
    chunkSpeedsOf<false>(dim, mass, vol, vol0, v0, v1, v2, modulus, mDense, denseRatio, out, n);
}

/// The max of the speeds over [begin, end) and (asked for) the first particle reaching it; vol0
/// null: one modulus.
double maxSpeed(const ParticleSet& p, std::size_t begin, std::size_t end, int dim, std::size_t* arg, double modulus,
                const double* vol0, double mDense, double denseRatio) {
  const double* v0 = p.v[0].data();
  const double* v1 = dim >= 2 ? p.v[1].data() : v0;
  const double* v2 = dim >= 3 ? p.v[2].data() : v0;
  const double* mass = p.mass.data();
  const double* vol = p.vol.data();
  constexpr std::size_t kChunk = 256;
  double s[kChunk];
  double cmax = 0;
  auto chunk = [&](std::size_t b, std::size_t n) {
    chunkSpeeds(dim, mass + b, vol + b, vol0 ? vol0 + b : nullptr, v0 + b, v1 + b, v2 + b, modulus, mDense,
                denseRatio, s, n);
  };
  for (std::size_t b = begin; b < end; b += kChunk) {
    const std::size_t n = std::min(kChunk, end - b);
    chunk(b, n);
    for (std::size_t k = 0; k < n; ++k)
      if (s[k] > cmax) cmax = s[k];  // a NaN speed is passed over
  }
  if (arg) {
    *arg = end;
    if (cmax > 0)
      for (std::size_t b = begin; b < end && *arg == end; b += kChunk) {
        const std::size_t n = std::min(kChunk, end - b);
        chunk(b, n);
        for (std::size_t k = 0; k < n; ++k)
          if (s[k] == cmax) {
            *arg = b + k;
            break;
          }
      }
  }
  return cmax;
}

}  // namespace

double maxElasticSignalSpeed(const ParticleSet& p, std::size_t begin, std::size_t end, int dim, std::size_t* arg,
                             double modulus) {
  return maxSpeed(p, begin, end, dim, arg, modulus, nullptr, modulus, 0.0);
}

double maxTwoModulusSignalSpeed(const ParticleSet& p, std::size_t begin, std::size_t end, int dim, std::size_t* arg,
                                double modulus, double denseModulus, double denseRatio) {
  return maxSpeed(p, begin, end, dim, arg, modulus, p.vol0.data(), denseModulus, denseRatio);
}

}  // namespace mpmice::mpm
