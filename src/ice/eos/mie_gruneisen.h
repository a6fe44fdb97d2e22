#pragma once
/// @brief Mie-Gruneisen with a linear Us-up Hugoniot as reference curve (scene name
/// `mie_gruneisen`; parameters `reference_density` rho0, `sound_speed` c0, `slope` s,
/// `gruneisen` Gamma0, `reference_pressure` p0). With eta = 1 - rho0/rho:
///   p_H = p0 + rho0 c0^2 eta / (1 - s eta)^2 (eta >= 0; linear in eta for eta < 0),
///   e_H = (p_H + p0) eta / (2 rho0),   p = p_H + Gamma0 rho0 (e - e_H)   (Gamma rho = const).
/// e = 0 at the reference state. Inverse by safeguarded Newton.
#include "ice/eos/eos.h"

namespace mpmice::ice {

class MieGruneisen final : public Eos {
 public:
  MieGruneisen(double rho0, double c0, double s, double gamma0, double p0, double cv)
      : Eos(cv), rho0_(rho0), c0_(c0), s_(s), g0_(gamma0), p0_(p0) {}
  [[nodiscard]] const char* name() const override { return "mie_gruneisen"; }
  void pressure(std::size_t n, const double* rho, const double* e, double* p) const override {
    for (std::size_t i = 0; i < n; ++i) {
      double dp;
      eval(rho[i], e[i], &p[i], &dp);
    }
  }
  void density(std::size_t n, const double* p, const double* e, double* rho, double* drhodp) const override;
  void soundSpeed2(std::size_t n, const double* rho, const double* e, double* c2) const override {
    for (std::size_t i = 0; i < n; ++i) {
      double p, dp;
      eval(rho[i], e[i], &p, &dp);
      c2[i] = dp + p * g0_ * rho0_ / (rho[i] * rho[i]);
    }
  }
  [[nodiscard]] double internalEnergy(double rho, double p) const override;
  /// p(rho, e) and dp/drho at fixed e.
  void eval(double rho, double e, double* p, double* dpdrho) const;

 private:
  double rho0_, c0_, s_, g0_, p0_;
};

}  // namespace mpmice::ice
