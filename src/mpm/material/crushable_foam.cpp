#include "mpm/material/crushable_foam.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "mpm/material/signal_speed.h"
#include "mpm/material/tensor.h"
#include "mpm/mpm_constants.h"

namespace mpmice::mpm {

CrushableFoam::CrushableFoam(const ElasticConstants& c, const CrushableFoamParams& f) : c_(c), f_(f) {
  if (!(f_.plateau > 0)) throw std::invalid_argument("crushable_foam: plateau_stress must be > 0");
  if (!(f_.densification > 0)) throw std::invalid_argument("crushable_foam: densification_strain must be > 0");
  if (!(f_.plasticPoisson > -1.0 && f_.plasticPoisson < 0.5))
    throw std::invalid_argument("crushable_foam: plastic_poissons_ratio must lie in (-1, 0.5), got " +
                                std::to_string(f_.plasticPoisson));
  if (!(f_.beta > 0)) throw std::invalid_argument("crushable_foam: hardening_beta must be > 0");
  if (!(f_.denseBulk > 0)) throw std::invalid_argument("crushable_foam: densified_bulk_modulus must be > 0");
  alpha_ = f_.alpha();
  shape_ = 1.0 + alpha_ * alpha_ / 9.0;
  denseJ_ = std::exp(-f_.denseStrain());
}

double CrushableFoam::maxSignalSpeed(const ParticleSet& p, std::size_t begin, std::size_t end, int dim,
                                     std::size_t* arg) const {
  return maxTwoModulusSignalSpeed(p, begin, end, dim, arg, c_.pWaveModulus(), f_.denseBulk + 4.0 * c_.G / 3.0, denseJ_);
}

double CrushableFoam::flowStress(double e) const { return f_.flowStress(e); }

Sym3 CrushableFoam::denseUpdate(const Mat3& L, const Sym3& s, double dt, double* eqps) const {
  // Compacted to the solid: the mean stress elastic with K_s, the deviator bounded by the flow stress
  // reached (radial return; eps_hat grows by the deviatoric plastic strain, short of eps_D).
  const double G = c_.G, eCap = f_.densification * (1.0 - 1e-12), e0 = *eqps;
  ElasticTrial t = elasticTrial(L, s, f_.denseBulk, G, dt);
  const double q = std::sqrt(1.5 * ddot(t.dev, t.dev)), Y = flowStress(std::min(e0, eCap));
  if (q > Y) {
    for (auto& c : t.dev) c *= Y / q;
    *eqps = std::min(e0 + (q - Y) / (3.0 * G), eCap);
  }
  return {t.dev[0] + t.mean, t.dev[1] + t.mean, t.dev[2] + t.mean, t.dev[3], t.dev[4], t.dev[5]};
}

Sym3 CrushableFoam::foamUpdate(const Mat3& L, const Sym3& s, double dt, double* eqps) const {
  const double K = c_.K, G = c_.G, a2 = alpha_ * alpha_, e0 = *eqps;
  ElasticTrial t = elasticTrial(L, s, K, G, dt);
  const double q = std::sqrt(1.5 * ddot(t.dev, t.dev));
  const double Y0 = flowStress(e0);
  if ((q * q + a2 * t.mean * t.mean) / shape_ > Y0 * Y0) {
    // Return: with multiplier dl (= d eps_hat) and Y = Y(e0 + dl) the end state is
    // q = q_tr / (1 + 3 G dl / (Y c)), sigma_m = sigma_m_tr / (1 + K alpha^2 dl / (Y c)), and the
    // consistency condition r(dl) = sqrt((q^2 + alpha^2 sigma_m^2) / c) - Y = 0, r(0) > 0 and
    // r -> -infinity below eps_D - e0: bisection-safeguarded secant on that bracket.
    auto residual = [&](double dl) {
      const double Y = flowStress(e0 + dl);
      const double qq = q / (1.0 + 3.0 * G * dl / (Y * shape_));
      const double mm = t.mean / (1.0 + K * a2 * dl / (Y * shape_));
      return std::sqrt((qq * qq + a2 * mm * mm) / shape_) - Y;
    };
    // The upper end: closer and closer below eps_D until r < 0 (the densification singularity,
    // alpha_2 > 0, guarantees it); a trial beyond even that leaves the state at the last one.
    const double room = f_.densification - e0;
    double lo = 0, rlo = residual(0.0), hi = room * (1.0 - 1e-3), rhi = residual(hi);
    for (double gap = 1e-6; rhi > 0 && gap > 1e-16; gap *= 1e-3) {
      lo = hi;
      rlo = rhi;
      hi = room * (1.0 - gap);
      rhi = residual(hi);
    }
    for (int it = 0; it < kFoamReturnMaxIterations && hi - lo > kFoamReturnTolerance * (e0 + hi); ++it) {
      double mid = rhi < 0 && rlo > 0 ? lo + (hi - lo) * rlo / (rlo - rhi) : 0.5 * (lo + hi);
      if (!(mid > lo && mid < hi) || it % 3 == 2) mid = 0.5 * (lo + hi);  // keep the bracket shrinking
      const double r = residual(mid);
      if (r > 0) {
        lo = mid;
        rlo = r;
      } else {
        hi = mid;
        rhi = r;
      }
      if (std::fabs(r) <= kFoamReturnTolerance * flowStress(e0 + mid)) {
        lo = hi = mid;
        break;
      }
    }
    const double dl = 0.5 * (lo + hi);
    const double Y = flowStress(e0 + dl);
    const double sd = 1.0 / (1.0 + 3.0 * G * dl / (Y * shape_));
    for (auto& c : t.dev) c *= sd;
    t.mean /= 1.0 + K * a2 * dl / (Y * shape_);
    *eqps = e0 + dl;
  }
  return {t.dev[0] + t.mean, t.dev[1] + t.mean, t.dev[2] + t.mean, t.dev[3], t.dev[4], t.dev[5]};
}

void CrushableFoam::updateStress(ParticleSet& p, std::size_t begin, std::size_t end, double dt) const {
  const double lnJd = std::log(denseJ_);
  for (std::size_t i = begin; i < end; ++i) {
    const Sym3 s = loadStress(p, i);
    const Mat3 L = loadL(p, i);
    const Sym3 D = symPart(L);
    // ln J at the step's end and (by the step's volumetric strain) at its start: a step that
    // crosses full density is split there, the foam's law before and the solid's after (or back).
    const double lnJ = std::log(p.vol[i] / p.vol0[i]), dlnJ = trace(D) * dt, lnJ0 = lnJ - dlnJ;
    const bool dense = lnJ <= lnJd, wasDense = lnJ0 <= lnJd;
    double e = p.eqps[i];
    Sym3 n;
    if (dense == wasDense || dlnJ == 0.0) {
      n = dense ? denseUpdate(L, s, dt, &e) : foamUpdate(L, s, dt, &e);
    } else {
      const double f = std::clamp((lnJd - lnJ0) / dlnJ, 0.0, 1.0);  // the share before the crossing
      const Sym3 mid = wasDense ? denseUpdate(L, s, f * dt, &e) : foamUpdate(L, s, f * dt, &e);
      n = dense ? denseUpdate(L, mid, (1.0 - f) * dt, &e) : foamUpdate(L, mid, (1.0 - f) * dt, &e);
    }
    p.eqps[i] = e;
    p.work[i] += stressWork(s, n, D, p.vol[i], dt);
    storeStress(p, i, n);
  }
}

}  // namespace mpmice::mpm
