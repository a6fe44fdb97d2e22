#pragma once
/// @brief The pointwise implicit exchange solve of one cell (or face) over N materials.
///
/// Solves (diag(s) + L(w)) x = b, where s_r >= 0 is material r's inertia (mass, or mass * cv for
/// heat), w_rs = w_sr >= 0 the coupling (dt V theta_r theta_s K_rs) and L(w) the graph Laplacian
/// (L_rr = sum_s w_rs, L_rs = -w_rs). This is
///     s_r x_r + sum_s w_rs (x_r - x_s) = b_r     (b_r = s_r x_r^L),
/// which conserves sum_r s_r x_r exactly. Elimination is GTH-style (Grassmann-Taksar-Heyman):
/// pivots are formed from row sums and off-diagonal magnitudes, never by subtraction, so the solve
/// is accurate for w / s up to 1e30 (K = 1e15) and for absent materials (s_r = 0, w_r* = 0: the
/// row is decoupled and x_r keeps its input value). Up to kMaxMaterials materials, nrhs
/// right-hand sides (velocity components) with one factorisation.
#include <cstddef>

#include "ice/state/lanes.h"

namespace mpmice::ice {

inline constexpr int kMaxMaterials = 16;

/// b = s x for each of the nrhs right-hand sides (x[c * n + r]), and row k's GTH pivot
/// s_k + sum_{j > k} w_kj (formed without subtraction); T: double, or lanes::v4d for the lanes.
template <class T>
inline void scaledRightHandSides(int n, int nrhs, const T* s, const T* x, T* b) {
  for (int c = 0; c < nrhs; ++c)
    for (int r = 0; r < n; ++r) b[c * n + r] = s[r] * x[c * n + r];
}
template <class T>
inline T gthPivot(int n, int k, const T* s, const T* w) {
  T a = s[k];
  for (int j = k + 1; j < n; ++j) a += w[k * n + j];
  return a;
}

/// The solve with n = N and nrhs = NRHS fixed at compile time where they are positive (the loops
/// then unroll; the same operations in the same order as with run-time counts).
template <int N, int NRHS>
inline void pointwiseExchangeFixed(int n, double* s, double* w, double* x, int nrhs) {
  if constexpr (N > 0) n = N;
  if constexpr (NRHS > 0) nrhs = NRHS;
  double b[3 * kMaxMaterials];
  double piv[kMaxMaterials];
  scaledRightHandSides(n, nrhs, s, x, b);
  for (int k = 0; k < n; ++k) {
    const double a = gthPivot(n, k, s, w);
    piv[k] = a;
    if (!(a > 0)) continue;  // absent and decoupled
    const double inv = 1.0 / a;
    for (int i = k + 1; i < n; ++i) {
      const double wik = w[i * n + k];
      if (wik == 0) continue;
      const double f = wik * inv;
      s[i] += f * s[k];
      for (int j = k + 1; j < n; ++j)
        if (j != i) w[i * n + j] += f * w[k * n + j];
      for (int c = 0; c < nrhs; ++c) b[c * n + i] += f * b[c * n + k];
    }
  }
  for (int k = n - 1; k >= 0; --k) {
    if (!(piv[k] > 0)) continue;  // keeps its input value
    for (int c = 0; c < nrhs; ++c) {
      double acc = b[c * n + k];
      for (int j = k + 1; j < n; ++j) acc += w[k * n + j] * x[c * n + j];
      x[c * n + k] = acc / piv[k];
    }
  }
}

/// s[n], w[n*n] (row-major, symmetric, diagonal ignored), x[c*n + r] in: b / s (the Lagrangian
/// value), out: the exchanged value. Modifies w and s (scratch). Two and three materials with one
/// to three right-hand sides run the unrolled solve.
inline void pointwiseExchange(int n, double* s, double* w, double* x, int nrhs) {
  if (n == 2 && nrhs == 1) return pointwiseExchangeFixed<2, 1>(n, s, w, x, nrhs);
  if (n == 2 && nrhs == 2) return pointwiseExchangeFixed<2, 2>(n, s, w, x, nrhs);
  if (n == 2 && nrhs == 3) return pointwiseExchangeFixed<2, 3>(n, s, w, x, nrhs);
  if (n == 3 && nrhs == 1) return pointwiseExchangeFixed<3, 1>(n, s, w, x, nrhs);
  if (n == 3 && nrhs == 2) return pointwiseExchangeFixed<3, 2>(n, s, w, x, nrhs);
  if (n == 3 && nrhs == 3) return pointwiseExchangeFixed<3, 3>(n, s, w, x, nrhs);
  pointwiseExchangeFixed<0, 0>(n, s, w, x, nrhs);
}

/// The couplings w_rq = scale K_rq theta_r theta_q of the exchange between n materials (K and w
/// n x n, row-major): scale = dt V in a cell (phase 10), dt at a face (phases 3 and 5).
template <int N>
inline void exchangeCouplingsFixed(int n, double scale, const double* K, const double* theta, double* w) {
  if constexpr (N > 0) n = N;
  for (int r = 0; r < n; ++r)
    for (int q = 0; q < n; ++q) w[r * n + q] = scale * K[r * n + q] * theta[r] * theta[q];
}
inline void exchangeCouplings(int n, double scale, const double* K, const double* theta, double* w) {
  if (n == 2) return exchangeCouplingsFixed<2>(n, scale, K, theta, w);
  if (n == 3) return exchangeCouplingsFixed<3>(n, scale, K, theta, w);
  exchangeCouplingsFixed<0>(n, scale, K, theta, w);
}

/// pointwiseExchangeFixed<N, NRHS> at four cells or faces (the lanes, lanes.h): the same
/// operations in the same order, each skipped elimination step (an absent pivot, a zero coupling)
/// a select of the values it leaves. s, w: scratch (modified); x[c * N + r] in: x^in, out:
/// exchanged.
template <int N, int NRHS>
inline void pointwiseExchangeLanes(lanes::v4d* s, lanes::v4d* w, lanes::v4d* x) {
  static_assert(N > 0 && N <= kMaxMaterials && NRHS > 0 && NRHS <= 3);
  using lanes::v4d, lanes::v4m, lanes::sel;
  v4d b[NRHS * N], piv[N];
  scaledRightHandSides(N, NRHS, s, x, b);
  for (int k = 0; k < N; ++k) {
    const v4d a = gthPivot(N, k, s, w);
    piv[k] = a;
    if (k + 1 == N) break;
    const v4m on = a > 0;
    const v4d inv = 1.0 / a;
    for (int i = k + 1; i < N; ++i) {
      const v4d wik = w[i * N + k];
      const v4m m = on & (wik != 0);
      const v4d f = wik * inv;
      s[i] = sel(m, s[i] + f * s[k], s[i]);
      for (int j = k + 1; j < N; ++j)
        if (j != i) w[i * N + j] = sel(m, w[i * N + j] + f * w[k * N + j], w[i * N + j]);
      for (int c = 0; c < NRHS; ++c) b[c * N + i] = sel(m, b[c * N + i] + f * b[c * N + k], b[c * N + i]);
    }
  }
  for (int k = N - 1; k >= 0; --k) {
    const v4m on = piv[k] > 0;
    for (int c = 0; c < NRHS; ++c) {
      v4d acc = b[c * N + k];
      for (int j = k + 1; j < N; ++j) acc += w[k * N + j] * x[c * N + j];
      x[c * N + k] = sel(on, acc / piv[k], x[c * N + k]);
    }
  }
}

/// exchangeCouplingsFixed<N> at four cells or faces: w_rq = scale K_rq theta_r theta_q.
template <int N>
inline void exchangeCouplingsLanes(double scale, const double* K, const lanes::v4d* theta, lanes::v4d* w) {
  for (int r = 0; r < N; ++r)
    for (int q = 0; q < N; ++q) w[r * N + q] = scale * K[r * N + q] * theta[r] * theta[q];
}

}  // namespace mpmice::ice
