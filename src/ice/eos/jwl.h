#pragma once
/// @brief Jones-Wilkins-Lee EOS of detonation products (scene name `jwl`; parameters `A`, `B`,
/// `R1`, `R2`, `omega`, `reference_density` rho0). With V = rho0 / rho:
///   p = A (1 - omega/(R1 V)) exp(-R1 V) + B (1 - omega/(R2 V)) exp(-R2 V) + omega rho e
///     = p_c(V) + omega rho (e - e_c(V)),   p_c = A exp(-R1 V) + B exp(-R2 V),
///   e_c = A / (R1 rho0) exp(-R1 V) + B / (R2 rho0) exp(-R2 V)   (de_c / dv = -p_c: the cold curve).
/// Temperature T = (e - e_c) / cv (as Uintah's JWL): along an isentrope e - e_c falls as v^-omega and
/// stays positive, and a state below the cold curve (p < p_c at its density) is below 0 K; with
/// T = e / cv such a state, e.g. 12 GPa at 1770 kg/m^3 for the PETN set (p_c 12.67 GPa), started and
/// reached T < 0 within microseconds of expansion (e_c -> 0).
/// Inverse by safeguarded Newton.
#include <algorithm>
#include <limits>

#include "ice/eos/eval_eos.h"

namespace mpmice::ice {

class Jwl final : public EvalEos<Jwl> {
 public:
  Jwl(double A, double B, double R1, double R2, double omega, double rho0, double cv)
      : EvalEos(cv), A_(A), B_(B), R1_(R1), R2_(R2), w_(omega), rho0_(rho0) {}
  [[nodiscard]] const char* name() const override { return "jwl"; }
  [[nodiscard]] double densityGuess(double p, double e) const {
    const double guess = e > 0 ? std::max(p / (w_ * e), 1e-6 * rho0_) : rho0_;
    return std::min(guess, 2.0 * rho0_);
  }
  [[nodiscard]] double maxDensity() const { return std::numeric_limits<double>::infinity(); }
  /// At e > 0, p -> 0+ as rho -> 0 (the exponentials vanish faster than omega rho e): the
  /// admissible pressures are p > 0. At e <= 0 (below the law's energy reference, which a trace of
  /// products in a mixed cell reaches) p(rho) dips below zero at small rho and has no simple lower
  /// end: no floor there (-inf); the density inversion's bracket marks what it cannot reach.
  void pressureFloor(std::size_t n, const double* e, double* pmin) const override {
    for (std::size_t i = 0; i < n; ++i) pmin[i] = e[i] > 0 ? 0.0 : -std::numeric_limits<double>::infinity();
  }
  [[nodiscard]] double soundSpeed2At(double rho, double p, double dpdrho) const { return dpdrho + p * w_ / rho; }
  [[nodiscard]] double internalEnergy(double rho, double p) const override;
  [[nodiscard]] double coldEnergy(double rho) const override;
  [[nodiscard]] bool hasColdEnergy() const override { return A_ != 0.0 || B_ != 0.0; }
  /// p(rho, e) and dp/drho at fixed e.
  void eval(double rho, double e, double* p, double* dpdrho) const;
  /// The e-independent part of p (the two exponential terms) and its rho-derivative.
  void cold(double rho, double* pc, double* dpc) const;

 private:
  double A_, B_, R1_, R2_, w_, rho0_;
};

}  // namespace mpmice::ice
