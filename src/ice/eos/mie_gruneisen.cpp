#include "ice/eos/mie_gruneisen.h"

#include <cmath>

namespace mpmice::ice {

void MieGruneisen::eval(double rho, double e, double* p, double* dpdrho) const {
  const double eta = 1.0 - rho0_ / rho;
  const double k = rho0_ * c0_ * c0_;
  double pH, dpH;
  if (eta >= 0) {
    const double d = 1.0 - s_ * eta;
    pH = p0_ + k * eta / (d * d);
    dpH = k * (1.0 + s_ * eta) / (d * d * d);
  } else {
    pH = p0_ + k * eta;
    dpH = k;
  }
  const double eH = (pH + p0_) * eta / (2.0 * rho0_);
  const double deH = (dpH * eta + pH + p0_) / (2.0 * rho0_);
  *p = pH + g0_ * rho0_ * (e - eH);
  *dpdrho = (dpH - g0_ * rho0_ * deH) * rho0_ / (rho * rho);
}

double MieGruneisen::internalEnergy(double rho, double p) const {
  double p0e, dp;
  eval(rho, 0.0, &p0e, &dp);
  return (p - p0e) / (g0_ * rho0_);
}

void MieGruneisen::density(std::size_t n, const double* p, const double* e, double* rho, double* drhodp) const {
  for (std::size_t i = 0; i < n; ++i) {
    const double ei = e[i];
    const double guess = rho0_ * (1.0 + (p[i] - p0_) / (rho0_ * c0_ * c0_));
    double r = invertPressure(p[i], guess > 0.1 * rho0_ ? guess : rho0_,
                              [&](double x, double* pp, double* dd) { eval(x, ei, pp, dd); });
    // The derivative at the root (the Hugoniot is singular at eta = 1/s; Newton stays below it).
    double pp, dd;
    eval(r, ei, &pp, &dd);
    rho[i] = r;
    drhodp[i] = dd > 0 ? 1.0 / dd : 0.0;
  }
}

}  // namespace mpmice::ice
