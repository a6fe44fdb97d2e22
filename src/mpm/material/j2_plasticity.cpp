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
    : ElasticWaveModel(c), sy0_(yieldStress), H_(hardening), failure_(failureStrain),
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

void J2Plasticity::yield(double e, double& sy, double& slope, double rateFactor) const {
  if (te_.empty()) {
    sy = sy0_ + H_ * e;
    slope = H_;
  } else if (te_.size() == 1) {
    sy = ts_[0];
    slope = 0;
  } else {
    std::size_t k = 1;
    while (k + 1 < te_.size() && e > te_[k]) ++k;
    slope = (ts_[k] - ts_[k - 1]) / (te_[k] - te_[k - 1]);
    sy = ts_[k - 1] + slope * (e - te_[k - 1]);
  }
  sy *= rateFactor;
  slope *= rateFactor;
}

void J2Plasticity::setRateDependence(double c, double p) {
  if (!(c > 0) || !(p > 0))
    throw std::invalid_argument("cowper_symonds: rate_c and rate_p must be > 0, got " + std::to_string(c) + ", " +
                                std::to_string(p));
  rateC_ = c;
  rateP_ = p;
}

void J2Plasticity::updateStress(ParticleSet& p, std::size_t begin, std::size_t end,
                                double dt) const {
  const double K = c_.K, G = c_.G;
  for (std::size_t i = begin; i < end; ++i) {
    const Sym3 s = loadStress(p, i);
    // Elastic trial (Jaumann rate).
    ElasticTrial trial = elasticTrial(loadL(p, i), s, K, G, dt);
    const Sym3& D = trial.D;
    double pm = trial.mean;  // mean stress
    Sym3& dev = trial.dev;
    // Cowper-Symonds: the flow stress times 1 + (rate / C)^(1/p), rate = sqrt(2/3 D':D').
    double rateFactor = 1.0;
    if (rateC_ > 0) {
      Sym3 dd = D;
      const double m = trace(D) / 3.0;
      for (int k = 0; k < 3; ++k) dd[k] -= m;
      rateFactor += std::pow(std::sqrt(2.0 / 3.0 * ddot(dd, dd)) / rateC_, 1.0 / rateP_);
    }
    Sym3 n;
    if (p.failed[i] != 0.0) {
      pm = std::min(pm, 0.0);
      n = {pm, pm, pm, 0, 0, 0};
    } else {
      const double q = std::sqrt(1.5 * ddot(dev, dev));
      double sy, h;
      yield(p.eqps[i], sy, h, rateFactor);
      if (q > sy) {
        // Radial return: q - 3G dg = sigma_y(eps_p + dg); Newton (exact for linear hardening).
        double dg = (q - sy) / (3.0 * G + h);
        for (int it = 0; it < kJ2MaxIterations; ++it) {
          yield(p.eqps[i] + dg, sy, h, rateFactor);
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
