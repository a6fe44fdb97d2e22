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

}  // namespace mpmice::ice
