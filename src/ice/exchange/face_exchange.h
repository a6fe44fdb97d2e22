#pragma once
/// @brief The pointwise momentum exchange at a face, assembled once for the face velocities
/// (phase 3) and the semi-implicit face mobilities (phase 5).
///
/// At the face between cells L and R each material r has the face volume fraction
/// theta_r,f = (theta_r,L + theta_r,R) / 2 and the face specific volume v_r,f (faceSpecificVolume:
/// the mass-weighted mean). The exchange solves, per face,
///     (theta_r,f / v_r,f) x_r + sum_q dt K_rq theta_r,f theta_q,f (x_r - x_q) = (theta_r,f / v_r,f) x_r^in
/// with pointwiseExchange(): x the predicted face velocities in phase 3, x = v_f (the mobility
/// without exchange) in phase 5, where it gives the face velocity's response to a pressure
/// gradient with the exchange.
#include <cstdint>
#include <vector>

#include "ice/exchange/pointwise_exchange.h"
#include "ice/state/ice_state.h"
#include "ice/state/lanes.h"

namespace mpmice::ice {

/// theta_r,f and v_r,f of every material at the face between the stored cells cL and cR (linear
/// indices of the cell fields' stored box).
inline void faceMaterialValues(const std::vector<MaterialState>& mat, std::int64_t cL, std::int64_t cR, double* theta,
                               double* v) {
  for (std::size_t r = 0; r < mat.size(); ++r) {
    const MaterialState& m = mat[r];
    const double *th = m.theta.data(), *ms = m.mass.data(), *sv = m.spvol.data();
    theta[r] = 0.5 * (th[cL] + th[cR]);
    v[r] = faceSpecificVolume(ms[cL], sv[cL], ms[cR], sv[cR]);
  }
}

/// The exchange at one face over n materials: x (in: x^in, out: exchanged) may alias v when nrhs
/// is 1; with nrhs right-hand sides x[c * n + r], one factorisation for all.
/// N > 0: n fixed at compile time (the loops unroll; the same operations in the same order).
template <int N>
inline void faceExchangeFixed(int n, double dt, const double* K, const double* theta, const double* v, double* x,
                              int nrhs) {
  if constexpr (N > 0) n = N;
  double s[kMaxMaterials], w[kMaxMaterials * kMaxMaterials];
  for (int r = 0; r < n; ++r) s[r] = theta[r] / v[r];
  exchangeCouplings(n, dt, K, theta, w);
  pointwiseExchange(n, s, w, x, nrhs);
}
inline void faceExchange(int n, double dt, const double* K, const double* theta, const double* v, double* x,
                         int nrhs = 1) {
  faceExchangeFixed<0>(n, dt, K, theta, v, x, nrhs);
}

/// faceExchangeFixed<N> with one right-hand side at four faces (the lanes).
template <int N>
inline void faceExchangeLanes(double dt, const double* K, const lanes::v4d* theta, const lanes::v4d* v,
                              lanes::v4d* x) {
  lanes::v4d s[N], w[N * N];
  for (int r = 0; r < N; ++r) s[r] = theta[r] / v[r];
  exchangeCouplingsLanes<N>(dt, K, theta, w);
  pointwiseExchangeLanes<N, 1>(s, w, x);
}

}  // namespace mpmice::ice
