#include "mpm/material/signal_speed.h"

#include <algorithm>
#include <cmath>

namespace mpmice::mpm {

namespace {

/// out[k] = sqrt(M / (m / V)) + |v| for the n particles from the pointers: a loop the compiler
/// vectorizes (distinct arrays: restrict parameters). Built for AVX2 as well as the x86-64
/// baseline and chosen at load time (target_clones): the divisions and square roots are its cost
/// and twice as many go per instruction; without FMA (not part of the avx2 target) the operations
/// and their bits are those of the baseline build.
template <int kDim>
void speeds(const double* __restrict__ mass, const double* __restrict__ vol, const double* __restrict__ v0,
            const double* __restrict__ v1, const double* __restrict__ v2, double modulus, double* __restrict__ out,
            std::size_t n) {
  for (std::size_t k = 0; k < n; ++k) {
    double vv = v0[k] * v0[k];
    if constexpr (kDim >= 2) vv += v1[k] * v1[k];
    if constexpr (kDim >= 3) vv += v2[k] * v2[k];
    out[k] = std::sqrt(modulus / (mass[k] / vol[k])) + std::sqrt(vv);
  }
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define MPMICE_SPEED_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define MPMICE_SPEED_CLONES
#endif

MPMICE_SPEED_CLONES
void chunkSpeeds(int dim, const double* mass, const double* vol, const double* v0, const double* v1, const double* v2,
                 double modulus, double* out, std::size_t n) {
  if (dim == 1)
    speeds<1>(mass, vol, v0, v1, v2, modulus, out, n);
  else if (dim == 2)
    speeds<2>(mass, vol, v0, v1, v2, modulus, out, n);
  else
    speeds<3>(mass, vol, v0, v1, v2, modulus, out, n);
}

}  // namespace

double maxElasticSignalSpeed(const ParticleSet& p, std::size_t begin, std::size_t end, int dim, std::size_t* arg,
                             double modulus) {
  const double* v0 = p.v[0].data();
  const double* v1 = dim >= 2 ? p.v[1].data() : v0;
  const double* v2 = dim >= 3 ? p.v[2].data() : v0;
  const double* mass = p.mass.data();
  const double* vol = p.vol.data();
  constexpr std::size_t kChunk = 256;
  double s[kChunk];
  double cmax = 0;
  for (std::size_t b = begin; b < end; b += kChunk) {
    const std::size_t n = std::min(kChunk, end - b);
    chunkSpeeds(dim, mass + b, vol + b, v0 + b, v1 + b, v2 + b, modulus, s, n);
    for (std::size_t k = 0; k < n; ++k)
      if (s[k] > cmax) cmax = s[k];  // a NaN speed is passed over
  }
  if (arg) {
    *arg = end;
    if (cmax > 0)
      for (std::size_t b = begin; b < end && *arg == end; b += kChunk) {
        const std::size_t n = std::min(kChunk, end - b);
        chunkSpeeds(dim, mass + b, vol + b, v0 + b, v1 + b, v2 + b, modulus, s, n);
        for (std::size_t k = 0; k < n; ++k)
          if (s[k] == cmax) {
            *arg = b + k;
            break;
          }
      }
  }
  return cmax;
}

}  // namespace mpmice::mpm
