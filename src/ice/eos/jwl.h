#pragma once
/// @brief Jones-Wilkins-Lee EOS of detonation products (scene name `jwl`; parameters `A`, `B`,
/// `R1`, `R2`, `omega`, `reference_density` rho0). With V = rho0 / rho:
///   p = A (1 - omega/(R1 V)) exp(-R1 V) + B (1 - omega/(R2 V)) exp(-R2 V) + omega rho e.
/// Inverse by safeguarded Newton.
#include "ice/eos/eos.h"

namespace mpmice::ice {

class Jwl final : public Eos {
 public:
  Jwl(double A, double B, double R1, double R2, double omega, double rho0, double cv)
      : Eos(cv), A_(A), B_(B), R1_(R1), R2_(R2), w_(omega), rho0_(rho0) {}
  [[nodiscard]] const char* name() const override { return "jwl"; }
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
      c2[i] = dp + p * w_ / rho[i];
    }
  }
  [[nodiscard]] double internalEnergy(double rho, double p) const override;
  /// p(rho, e) and dp/drho at fixed e.
  void eval(double rho, double e, double* p, double* dpdrho) const;
  /// The e-independent part of p (the two exponential terms) and its rho-derivative.
  void cold(double rho, double* pc, double* dpc) const;

 private:
  double A_, B_, R1_, R2_, w_, rho0_;
};

}  // namespace mpmice::ice
