#pragma once
/// @brief Mie-Gruneisen with a linear Us-up Hugoniot as reference curve (scene name
/// `mie_gruneisen`; parameters `reference_density` rho0, `sound_speed` c0, `slope` s,
/// `gruneisen` Gamma0, `reference_pressure` p0). With eta = 1 - rho0/rho:
///   p_H = p0 + rho0 c0^2 eta / (1 - s eta)^2 (eta >= 0; linear in eta for eta < 0),
///   e_H = (p_H + p0) eta / (2 rho0),   p = p_H + Gamma0 rho0 (e - e_H)   (Gamma rho = const).
/// e = 0 at the reference state, which is at temperature T0 (`reference_temperature`, default 0):
/// T = T0 + e / cv (a constant cold energy -cv T0). Inverse by safeguarded Newton on (0, rho0 s / (s - 1)); every
/// pressure is admissible at fixed e (p -> -inf as rho -> 0: tension, no cavitation model).
#include <limits>

#include "ice/eos/eval_eos.h"

namespace mpmice::ice {

class MieGruneisen final : public EvalEos<MieGruneisen> {
 public:
  MieGruneisen(double rho0, double c0, double s, double gamma0, double p0, double cv, double t0 = 0.0)
      : EvalEos(cv), rho0_(rho0), c0_(c0), s_(s), g0_(gamma0), p0_(p0), t0_(t0) {}
  [[nodiscard]] const char* name() const override { return "mie_gruneisen"; }
  /// The linear Hugoniot's density at p (rho0 where that falls below 0.1 rho0). The derivative
  /// at the root: the Hugoniot is singular at eta = 1/s; Newton stays below it.
  [[nodiscard]] double densityGuess(double p, double /*e*/) const {
    const double guess = rho0_ * (1.0 + (p - p0_) / (rho0_ * c0_ * c0_));
    return guess > 0.1 * rho0_ ? guess : rho0_;
  }
  /// The Hugoniot's singular density (eta = 1/s: p -> inf), the end of the density range.
  [[nodiscard]] double maxDensity() const {
    return s_ > 1 ? rho0_ * s_ / (s_ - 1.0) : std::numeric_limits<double>::infinity();
  }
  [[nodiscard]] double soundSpeed2At(double rho, double p, double dpdrho) const {
    return dpdrho + p * g0_ * rho0_ / (rho * rho);
  }
  [[nodiscard]] double internalEnergy(double rho, double p) const override;
  /// -cv T0: the reference state (e = 0) is at T0, not at 0 K.
  [[nodiscard]] double coldEnergy(double /*rho*/) const override { return -cv() * t0_; }
  [[nodiscard]] bool hasColdEnergy() const override { return t0_ != 0.0; }
  /// p(rho, e) and dp/drho at fixed e.
  void eval(double rho, double e, double* p, double* dpdrho) const;

 private:
  double rho0_, c0_, s_, g0_, p0_, t0_;
};

}  // namespace mpmice::ice
