#pragma once
/// @brief Small 3x3 tensor helpers for the constitutive updates (row-major arrays, inline).
///
/// Particles store the velocity gradient L and deformation gradient F as nine columns and the
/// symmetric Cauchy stress as six (xx, yy, zz, xy, yz, xz); these helpers gather one particle's
/// values into registers and scatter them back. In 1D / 2D the out-of-plane components are not
/// stored (ParticleSet, ParticleLayout): loadF / loadL / loadStress give their exact values (0;
/// F_zz 1) and storeStress leaves them out (a planar model keeps them 0).
#include <array>
#include <cmath>
#include <cstddef>

#include "mpm/particles/particle_set.h"

namespace mpmice::mpm {

using Mat3 = std::array<double, 9>;
using Sym3 = std::array<double, 6>;  // xx, yy, zz, xy, yz, xz

inline Mat3 loadMat(const std::array<ParticleSet::Col, 9>& c, std::size_t i) {
  Mat3 m;
  for (int k = 0; k < 9; ++k) m[k] = c[k][i];
  return m;
}
/// F or L of particle i; `zz` the value of the zz component where it is not stored.
inline Mat3 loadMat(const ParticleSet& p, const std::array<ParticleSet::Col, 9>& c, std::size_t i, double zz) {
  if (p.layout().dim < 3) return {c[0][i], c[1][i], 0.0, c[3][i], c[4][i], 0.0, 0.0, 0.0, zz};
  return loadMat(c, i);
}
inline Mat3 loadF(const ParticleSet& p, std::size_t i) { return loadMat(p, p.F, i, 1.0); }
inline Mat3 loadL(const ParticleSet& p, std::size_t i) { return loadMat(p, p.L, i, 0.0); }
inline Sym3 loadStress(const ParticleSet& p, std::size_t i) {
  if (p.layout().dim < 3) return {p.stress[kXX][i], p.stress[kYY][i], p.stress[kZZ][i], p.stress[kXY][i], 0.0, 0.0};
  Sym3 s;
  for (int k = 0; k < 6; ++k) s[k] = p.stress[k][i];
  return s;
}
inline void storeStress(ParticleSet& p, std::size_t i, const Sym3& s) {
  const int n = p.layout().dim < 3 ? 4 : 6;  // kXX, kYY, kZZ, kXY first
  for (int k = 0; k < n; ++k) p.stress[k][i] = s[k];
}
/// Symmetric part D of a row-major L, as Sym3.
inline Sym3 symPart(const Mat3& L) {
  return {L[0], L[4], L[8], 0.5 * (L[1] + L[3]), 0.5 * (L[5] + L[7]), 0.5 * (L[2] + L[6])};
}
inline double trace(const Sym3& s) { return s[0] + s[1] + s[2]; }
/// s : t for symmetric tensors (off-diagonals count twice).
inline double ddot(const Sym3& s, const Sym3& t) {
  return s[0] * t[0] + s[1] * t[1] + s[2] * t[2] + 2.0 * (s[3] * t[3] + s[4] * t[4] + s[5] * t[5]);
}
inline double det(const Mat3& a) {
  return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
         a[2] * (a[3] * a[7] - a[4] * a[6]);
}
/// The Jaumann co-rotational term W s - s W with W = skew(L), returned as Sym3.
inline Sym3 jaumannSpin(const Mat3& L, const Sym3& s) {
  const double w01 = 0.5 * (L[1] - L[3]), w02 = 0.5 * (L[2] - L[6]), w12 = 0.5 * (L[5] - L[7]);
  // W = [[0, w01, w02], [-w01, 0, w12], [-w02, -w12, 0]]; S full symmetric.
  const double S[3][3] = {{s[0], s[3], s[5]}, {s[3], s[1], s[4]}, {s[5], s[4], s[2]}};
  const double W[3][3] = {{0, w01, w02}, {-w01, 0, w12}, {-w02, -w12, 0}};
  double R[3][3];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      // The diagonal of W is an exact 0: its products add exact zeros and are left out.
      double ws = 0, sw = 0;
      for (int c = 0; c < 3; ++c) {
        if (c != a) ws += W[a][c] * S[c][b];
        if (c != b) sw += S[a][c] * W[c][b];
      }
      R[a][b] = ws - sw;
    }
  return {R[0][0], R[1][1], R[2][2], R[0][1], R[1][2], R[0][2]};
}
/// The hypoelastic trial state of a step (Jaumann rate): the rate of deformation D = sym L, the
/// mean stress and the deviator after dt with bulk modulus K and shear modulus G.
struct ElasticTrial {
  Sym3 D;
  double mean;
  Sym3 dev;
};
inline ElasticTrial elasticTrial(const Mat3& L, const Sym3& s, double K, double G, double dt) {
  ElasticTrial t;
  t.D = symPart(L);
  const Sym3 spin = jaumannSpin(L, s);
  const double trD = trace(t.D), oldMean = trace(s) / 3.0;
  t.mean = oldMean + dt * K * trD;
  for (int k = 0; k < 6; ++k) {
    const double sd = s[k] - (k < 3 ? oldMean : 0.0);
    const double dd = t.D[k] - (k < 3 ? trD / 3.0 : 0.0);
    t.dev[k] = sd + dt * (2.0 * G * dd + spin[k]);
  }
  return t;
}
/// Stress work of one particle over a step, midpoint rule: V (s_old + s_new)/2 : D dt.
inline double stressWork(const Sym3& sOld, const Sym3& sNew, const Sym3& D, double vol, double dt) {
  Sym3 m;
  for (int k = 0; k < 6; ++k) m[k] = 0.5 * (sOld[k] + sNew[k]);
  return vol * ddot(m, D) * dt;
}

}  // namespace mpmice::mpm
