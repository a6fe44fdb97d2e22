#include "mpm/material/j2_plasticity.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "mpm/material/tensor.h"
#include "mpm/mpm_constants.h"

namespace mpmice::mpm {

J2Plasticity::J2Plasticity(const ElasticConstants& c, double yieldStress, double hardening,
                           double failureStrain, std::vector<double> tableStrain,
                           std::vector<double> tableStress)
    : c_(c), sy0_(yieldStress), H_(hardening), failure_(failureStrain),
      te_(std::move(tableStrain)), ts_(std::move(tableStress)) {
  if (te_.size() != ts_.size())
    throw std::invalid_argument("j2_plasticity: tables plastic_strain and stress differ in length (" +
                                std::to_string(te_.size()) + " vs " + std::to_string(ts_.size()) + ")");
  for (std::size_t k = 1; k < te_.size(); ++k)
    if (!(te_[k] > te_[k - 1]))
      throw std::invalid_argument("j2_plasticity: table plastic_strain must increase strictly");
  if (te_.empty() && !(sy0_ > 0))
    throw std::invalid_argument("j2_plasticity: yield_stress must be > 0, got " + std::to_string(sy0_));
}

void J2Plasticity::yield(double e, double& sy, double& slope) const {
  if (te_.empty()) {
    sy = sy0_ + H_ * e;
    slope = H_;
    return;
  }
  if (te_.size() == 1) {
    sy = ts_[0];
    slope = 0;
    return;
  }
  std::size_t k = 1;
  while (k + 1 < te_.size() && e > te_[k]) ++k;
  slope = (ts_[k] - ts_[k - 1]) / (te_[k] - te_[k - 1]);
  sy = ts_[k - 1] + slope * (e - te_[k - 1]);
}

void J2Plasticity::updateStress(ParticleSet& p, std::size_t begin, std::size_t end,
                                double dt) const {
  const double K = c_.K, G = c_.G;
  for (std::size_t i = begin; i < end; ++i) {
    const Mat3 L = loadMat(p.L, i);
    const Sym3 D = symPart(L);
    const Sym3 s = loadStress(p, i);
    // Elastic trial (Jaumann rate).
    const Sym3 spin = jaumannSpin(L, s);
    const double trD = trace(D);
    double pm = trace(s) / 3.0 + dt * K * trD;  // mean stress
    Sym3 dev;
    const double oldMean = trace(s) / 3.0;
    for (int k = 0; k < 6; ++k) {
      const double sd = s[k] - (k < 3 ? oldMean : 0.0);
      const double dd = D[k] - (k < 3 ? trD / 3.0 : 0.0);
      dev[k] = sd + dt * (2.0 * G * dd + spin[k]);
    }
    Sym3 n;
    if (p.failed[i] != 0.0) {
      pm = std::min(pm, 0.0);
      n = {pm, pm, pm, 0, 0, 0};
    } else {
      const double q = std::sqrt(1.5 * ddot(dev, dev));
      double sy, h;
      yield(p.eqps[i], sy, h);
      if (q > sy) {
        // Radial return: q - 3G dg = sigma_y(eps_p + dg); Newton (exact for linear hardening).
        double dg = (q - sy) / (3.0 * G + h);
        for (int it = 0; it < kJ2MaxIterations; ++it) {
          yield(p.eqps[i] + dg, sy, h);
          const double r = q - 3.0 * G * dg - sy;
          if (std::fabs(r) <= kJ2ReturnTolerance * q) break;
          dg += r / (3.0 * G + h);
        }
        const double scale = 1.0 - 3.0 * G * dg / q;
        for (auto& c : dev) c *= scale;
        p.eqps[i] += dg;
        if (failure_ > 0 && p.eqps[i] >= failure_) {
          p.failed[i] = 1.0;
          pm = std::min(pm, 0.0);
          dev = {0, 0, 0, 0, 0, 0};
        }
      }
      n = {dev[0] + pm, dev[1] + pm, dev[2] + pm, dev[3], dev[4], dev[5]};
    }
    p.work[i] += stressWork(s, n, D, p.vol[i], dt);
    storeStress(p, i, n);
  }
}

}  // namespace mpmice::mpm
