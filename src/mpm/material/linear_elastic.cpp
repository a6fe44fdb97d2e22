#include "mpm/material/linear_elastic.h"

#include <cmath>

#include "mpm/material/tensor.h"

namespace mpmice::mpm {

void LinearElastic::updateStress(ParticleSet& p, std::size_t begin, std::size_t end,
                                 double dt) const {
  const double lam = c_.lambda(), twoG = 2.0 * c_.G;
  if (p.layout().dim < 3) {
    updatePlanar(p, begin, end, dt);
    return;
  }
  // 3D: the column pointers in locals and no dependence assumed between particles (ivdep, the
  // columns are distinct): the loop vectorizes, lane by lane the same operations.
  const double* Lc[9];
  double* Sc[6];
  for (int k = 0; k < 9; ++k) Lc[k] = p.L[k].data();
  for (int k = 0; k < 6; ++k) Sc[k] = p.stress[k].data();
  const double* vol = p.vol.data();
  double* work = p.work.data();
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC ivdep
#endif
  for (std::size_t i = begin; i < end; ++i) {
    Mat3 L;
    for (int k = 0; k < 9; ++k) L[k] = Lc[k][i];
    const Sym3 D = symPart(L);
    Sym3 s;
    for (int k = 0; k < 6; ++k) s[k] = Sc[k][i];
    const Sym3 spin = jaumannSpin(L, s);
    const double lt = lam * trace(D);
    Sym3 n;
    for (int k = 0; k < 6; ++k) n[k] = s[k] + dt * (twoG * D[k] + (k < 3 ? lt : 0.0) + spin[k]);
    work[i] += stressWork(s, n, D, vol[i], dt);
    for (int k = 0; k < 6; ++k) Sc[k][i] = n[k];
  }
}

// The loop above with the out-of-plane components of L and of the stress at their exact zeros
// (1D / 2D; ParticleLayout): every operation of it whose operands are not all such zeros, in the
// same order, so the stored components get the same bits. Where the loop adds a product of exact
// zeros to a sum started at 0, the sum is its only other term t "canonicalised" (0 + t: -0 -> +0),
// written t + 0.0 here. With a = w01 s_xy:
//   spin_xx = (a + 0) - (-a + 0), spin_yy = (-a + 0) - (a + 0), spin_zz = +0,
//   spin_xy = (w01 s_yy + 0) - (s_xx w01 + 0); D_zz = +0 so 2G D_zz + lt = lt + 0.
namespace {
// The loop of updatePlanar over distinct columns: restrict-qualified parameters (GCC honours
// __restrict__ on parameters, not on locals), so it vectorizes, lane by lane the same operations.
void planarUpdate(const double* __restrict__ L0c, const double* __restrict__ L1c, const double* __restrict__ L3c,
                  const double* __restrict__ L4c, double* __restrict__ sxx, double* __restrict__ syy,
                  double* __restrict__ szz, double* __restrict__ sxy, const double* __restrict__ vol,
                  double* __restrict__ work, std::size_t begin, std::size_t end, double dt, double lam,
                  double twoG) {
  for (std::size_t i = begin; i < end; ++i) {
    const double L0 = L0c[i], L1 = L1c[i], L3 = L3c[i], L4 = L4c[i];
    const Sym3 s = {sxx[i], syy[i], szz[i], sxy[i], 0.0, 0.0};
    const Sym3 D = {L0, L4, 0.0, 0.5 * (L1 + L3), 0.0, 0.0};
    const double w01 = 0.5 * (L1 - L3);
    const double a = w01 * s[3], pa = a + 0.0, ma = -a + 0.0;
    const double lt = lam * ((L0 + L4) + 0.0);
    const Sym3 n = {s[0] + dt * (twoG * L0 + lt + (pa - ma)),
                    s[1] + dt * (twoG * L4 + lt + (ma - pa)),
                    s[2] + dt * (lt + 0.0),
                    s[3] + dt * (twoG * D[3] + 0.0 + ((w01 * s[1] + 0.0) - (s[0] * w01 + 0.0))),
                    0.0,
                    0.0};
    work[i] += stressWork(s, n, D, vol[i], dt);
    sxx[i] = n[0];
    syy[i] = n[1];
    szz[i] = n[2];
    sxy[i] = n[3];
  }
}
}  // namespace

void LinearElastic::updatePlanar(ParticleSet& p, std::size_t begin, std::size_t end, double dt) const {
  planarUpdate(p.L[0].data(), p.L[1].data(), p.L[3].data(), p.L[4].data(), p.stress[kXX].data(),
               p.stress[kYY].data(), p.stress[kZZ].data(), p.stress[kXY].data(), p.vol.data(), p.work.data(),
               begin, end, dt, c_.lambda(), 2.0 * c_.G);
}

}  // namespace mpmice::mpm
