#pragma once
/// @brief The solid equation of state ICE's equilibrium pressure needs: a bulk-modulus law with
/// the paper's smooth tension branch (scene name `solid_bulk`).
///
/// Above the threshold pressure p_ref (about 1 atm) the solid follows the bulk-modulus law
///     p = p_ref + K/2 (rho/rho0 - rho0/rho),   rho(p) = rho0 (g + sqrt(g^2 + 1)),  g = (p - p_ref)/K,
/// whose slope at rho0 is K/rho0. Below it (tension) the law is replaced by the power law
///     p = p_ref (rho/rho0)^n,  n = K/p_ref,
/// continuous and smooth at the threshold (same value and slope at rho0) and going to zero as the
/// specific volume grows, so sum_r rho_r v_r(p) = 1 always has a root. Parameters are the scene's
/// `bulk_modulus`, `threshold_pressure`, `reference_density`; header-only, no MPM dependency.
#include <cmath>
#include <stdexcept>
#include <string>

namespace mpmice::core {

class SolidBulkEos {
 public:
  SolidBulkEos() = default;
  /// K > 0, p_ref > 0, rho0 > 0 (throws std::invalid_argument naming the bad parameter).
  SolidBulkEos(double bulkModulus, double thresholdPressure, double referenceDensity)
      : K_(bulkModulus), pref_(thresholdPressure), rho0_(referenceDensity) {
    check(K_, "bulk_modulus");
    check(pref_, "threshold_pressure");
    check(rho0_, "reference_density");
  }

  [[nodiscard]] double bulkModulus() const { return K_; }
  [[nodiscard]] double thresholdPressure() const { return pref_; }
  [[nodiscard]] double referenceDensity() const { return rho0_; }

  /// Pressure at density rho (> 0).
  [[nodiscard]] double pressure(double rho) const {
    const double s = rho / rho0_;
    if (s < 1.0) return pref_ * std::pow(s, K_ / pref_);
    return pref_ + 0.5 * K_ * (s - 1.0 / s);
  }
  /// dp/drho at density rho (the squared sound speed of the EOS).
  [[nodiscard]] double dpdrho(double rho) const {
    const double s = rho / rho0_;
    if (s < 1.0) return (K_ / rho0_) * std::pow(s, K_ / pref_ - 1.0);
    return 0.5 * K_ * (1.0 / rho0_ + rho0_ / (rho * rho));
  }
  /// Density at pressure p (> 0; the tension branch needs p > 0).
  [[nodiscard]] double density(double p) const {
    if (p < pref_) {
      if (!(p > 0)) return 0.0;  // infinite specific volume: the branch's limit
      return rho0_ * std::pow(p / pref_, pref_ / K_);
    }
    const double g = (p - pref_) / K_;
    return rho0_ * (g + std::sqrt(g * g + 1.0));
  }
  /// Specific volume v(p) = 1 / rho(p).
  [[nodiscard]] double specificVolume(double p) const { return 1.0 / density(p); }
  /// d v / d p at pressure p.
  [[nodiscard]] double dvdp(double p) const {
    const double rho = density(p);
    return -1.0 / (rho * rho * dpdrho(rho));
  }
  /// Isothermal compressibility kappa = -(1/v) dv/dp = 1/(rho dp/drho).
  [[nodiscard]] double compressibility(double p) const {
    const double rho = density(p);
    return 1.0 / (rho * dpdrho(rho));
  }
  [[nodiscard]] double soundSpeed(double rho) const { return std::sqrt(dpdrho(rho)); }

 private:
  static void check(double v, const char* key) {
    if (!(v > 0))
      throw std::invalid_argument(std::string("solid_bulk EOS: ") + key + " must be > 0, got " +
                                  std::to_string(v));
  }
  double K_ = 1, pref_ = 1, rho0_ = 1;
};

}  // namespace mpmice::core
