#pragma once
/// @brief Safeguarded Newton inversion of an increasing pressure law p(rho) on (0, rhoMax)
/// (header-only helper): Newton steps that leave the bracket become bisection, so the iterate
/// never reaches a law's singular density (Mie-Gruneisen's eta = 1/s).
#include <cmath>
#include <limits>

namespace mpmice::ice {

template <class PDp>
double invertPressure(double target, double guess, PDp&& pdp, double rhoMax) {
  double lo = 0.0, hi = rhoMax;
  double rho = guess > 0 && guess < hi ? guess : (std::isfinite(hi) ? 0.5 * hi : 1.0);
  for (int it = 0; it < 200; ++it) {
    double p = 0, dp = 0;
    pdp(rho, &p, &dp);
    const double f = p - target;
    if (std::abs(f) <= 1e-14 * (std::abs(target) + std::abs(p)) + 1e-300) return rho;
    if (f < 0) lo = rho; else hi = rho;
    double next = (dp > 0 && std::isfinite(dp)) ? rho - f / dp : -1.0;
    if (!(next > lo && next < hi)) next = std::isfinite(hi) ? 0.5 * (lo + hi) : 2.0 * rho;
    if (std::isfinite(hi) && hi - lo <= 1e-15 * hi) return next;
    rho = next;
  }
  return rho;
}

}  // namespace mpmice::ice
