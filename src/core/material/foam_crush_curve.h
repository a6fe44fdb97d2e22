#pragma once
/// @brief The solid equation of state ICE's equilibrium pressure needs for a crushable foam: the
/// foam's own hydrostatic crush curve (scene name `crush_curve`, chosen for a `crushable_foam`
/// solid by name), so that ICE's volume of the foam at a pressure is the volume the particles
/// reach under a hydrostatic crush to it, to full density and beyond.
///
/// With compression eps = ln(rho / rho0) and P = p - p_ref (p_ref the threshold pressure, about
/// 1 atm, at which the foam is stress-free), the curve is the crushable_foam model's response to a
/// hydrostatic crush (src/mpm/material/crushable_foam.h; k = sqrt(1 + alpha^2 / 9) / alpha):
///   elastic     P = K eps                                  up to P_y = k sigma_p,
///   crushing    P = k Y(eps_hat),  eps = P / K + eps_hat / k  (Y the model's flow stress),
///   compacted   P = P_d + K_s (eps - eps_d)                 from the full density, eps_d = -ln J_d,
/// J_d = exp(-3 alpha^2 eps_D / (9 + alpha^2)) and P_d the crushing branch's value there. Below
/// p_ref (tension) the branch of solid_bulk: p = p_ref (rho / rho0)^(K / p_ref), the same value and
/// slope at rho0. The curve is a loading curve: ICE reads the foam's volume from it whatever the
/// foam's history (an unloaded, crushed foam is read as re-expanded; the particles keep their own
/// state). The bulk-modulus law with the foam's K (37 MPa for the underwater scenes' foam) put the
/// foam at 4390 kg/m^3 in a cell at 0.3 GPa, 1.6 times the density of its solid.
/// Header-only, no MPM dependency; parameters are the crushable_foam model's.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace mpmice::core {

/// The crushable foam's hardening (the crushable_foam model's keys; src/mpm/material/crushable_foam.h
/// takes these too): Y(eps_hat) = sigma_p + gamma eps_hat / eps_D + alpha_2 ln(1 / (1 - (eps_hat / eps_D)^beta)).
struct FoamHardening {
  double plateau = 0;         // sigma_p [Pa]
  double densification = 0;  // eps_D
  double plasticPoisson = 0;  // nu_p
  double gamma = 0;          // [Pa]
  double alpha2 = 0;         // [Pa]
  double beta = 1;
  double denseBulk = 0;       // K_s [Pa], the compacted solid's bulk modulus

  /// Flow stress Y at eps_hat (< eps_D; infinite at eps_D) and its slope dY / d eps_hat.
  [[nodiscard]] double flowStress(double h) const {
    const double x = h / densification;
    return plateau + gamma * x - alpha2 * std::log1p(-std::pow(x, beta));
  }
  [[nodiscard]] double flowSlope(double h) const {
    const double x = h / densification, xb = std::pow(x, beta);
    const double d = alpha2 * beta * (x > 0 ? xb / x : (beta == 1.0 ? 1.0 : 0.0)) / (1.0 - xb);
    return (gamma + d) / densification;
  }
  /// The yield surface's shape factor alpha^2 = 9 (1 - 2 nu_p) / (2 (1 + nu_p)).
  [[nodiscard]] double alpha() const { return std::sqrt(9.0 * (1.0 - 2.0 * plasticPoisson) / (2.0 * (1.0 + plasticPoisson))); }
  /// -ln J_d, the volumetric strain at full density: 3 alpha^2 eps_D / (9 + alpha^2).
  [[nodiscard]] double denseStrain() const {
    const double a = alpha();
    return 3.0 * a * a * densification / (9.0 + a * a);
  }
};

struct FoamCrushParams {
  double bulkModulus = 0;        // K [Pa], the uncrushed foam's
  double thresholdPressure = 0;  // p_ref [Pa]
  double referenceDensity = 0;   // rho0 [kg/m^3]
  FoamHardening hardening;
};

class FoamCrushCurve {
 public:
  FoamCrushCurve() = default;
  /// Throws std::invalid_argument naming the bad parameter (the crushable_foam keys).
  explicit FoamCrushCurve(const FoamCrushParams& f) : f_(f), y_(f.hardening) {
    check(f_.bulkModulus > 0, "bulk_modulus", f_.bulkModulus);
    check(f_.thresholdPressure > 0, "threshold_pressure", f_.thresholdPressure);
    check(f_.referenceDensity > 0, "reference_density", f_.referenceDensity);
    check(y_.plateau > 0, "plateau_stress", y_.plateau);
    check(y_.densification > 0, "densification_strain", y_.densification);
    check(y_.plasticPoisson > -1.0 && y_.plasticPoisson < 0.5, "plastic_poissons_ratio", y_.plasticPoisson);
    check(y_.gamma >= 0, "hardening_gamma", y_.gamma);
    check(y_.alpha2 >= 0, "hardening_alpha2", y_.alpha2);
    check(y_.beta > 0, "hardening_beta", y_.beta);
    check(y_.denseBulk > 0, "densified_bulk_modulus", y_.denseBulk);
    const double a = y_.alpha();
    k_ = std::sqrt(1.0 + a * a / 9.0) / a;
    epsD_ = y_.denseStrain();
    Py_ = k_ * y_.plateau;
    epsY_ = Py_ / f_.bulkModulus;
    if (epsY_ >= epsD_) {  // fully dense before it yields: elastic to J_d
      hatD_ = 0, epsY_ = epsD_, Pd_ = f_.bulkModulus * epsD_;
    } else {
      hatD_ = hatAtStrain(epsD_);
      Pd_ = k_ * y_.flowStress(hatD_);
    }
  }

  [[nodiscard]] double bulkModulus() const { return f_.bulkModulus; }
  [[nodiscard]] double thresholdPressure() const { return f_.thresholdPressure; }
  [[nodiscard]] double referenceDensity() const { return f_.referenceDensity; }
  /// The volume ratio V / V0 at full density, J_d, and the pressure p_ref + P_d reached there.
  [[nodiscard]] double denseVolumeRatio() const { return std::exp(-epsD_); }
  [[nodiscard]] double densePressure() const { return f_.thresholdPressure + Pd_; }

  /// Pressure at density rho (> 0).
  [[nodiscard]] double pressure(double rho) const {
    const double s = rho / f_.referenceDensity;
    if (s < 1.0) return f_.thresholdPressure * std::pow(s, f_.bulkModulus / f_.thresholdPressure);
    return f_.thresholdPressure + crushPressure(std::log(s));
  }
  /// dp/drho at density rho.
  [[nodiscard]] double dpdrho(double rho) const {
    const double s = rho / f_.referenceDensity;
    if (s < 1.0) return (f_.bulkModulus / f_.referenceDensity) * std::pow(s, f_.bulkModulus / f_.thresholdPressure - 1.0);
    return crushModulus(std::log(s)) / rho;
  }
  /// Density at pressure p (0 at p <= 0: the tension branch's limit).
  [[nodiscard]] double density(double p) const {
    const double pref = f_.thresholdPressure, rho0 = f_.referenceDensity;
    if (p < pref) {
      if (!(p > 0)) return 0.0;
      return rho0 * std::pow(p / pref, pref / f_.bulkModulus);
    }
    return rho0 * std::exp(crushStrain(p - pref));
  }

  /// P(eps) of the compression branch (eps >= 0).
  [[nodiscard]] double crushPressure(double eps) const {
    if (eps <= epsY_) return f_.bulkModulus * eps;
    if (eps >= epsD_) return Pd_ + y_.denseBulk * (eps - epsD_);
    return k_ * y_.flowStress(hatAtStrain(eps));
  }
  /// eps(P), the inverse of crushPressure (P >= 0).
  [[nodiscard]] double crushStrain(double P) const {
    if (P <= f_.bulkModulus * epsY_) return P / f_.bulkModulus;
    if (P >= Pd_) return epsD_ + (P - Pd_) / y_.denseBulk;
    const double h = hatAtPressure(P);
    return P / f_.bulkModulus + h / k_;
  }
  /// dP/deps of the compression branch.
  [[nodiscard]] double crushModulus(double eps) const {
    if (eps <= epsY_) return f_.bulkModulus;
    if (eps >= epsD_) return y_.denseBulk;
    const double h = hatAtStrain(eps);
    const double dP = k_ * y_.flowSlope(h);  // dP / d eps_hat
    return dP / (dP / f_.bulkModulus + 1.0 / k_);
  }

 private:
  /// The volumetric strain at eps_hat on the crushing branch.
  [[nodiscard]] double strainAt(double h) const { return k_ * y_.flowStress(h) / f_.bulkModulus + h / k_; }
  /// eps_hat in [0, eps_D) with g(eps_hat) = target, g increasing with slope dg: Newton's steps
  /// kept inside a shrinking bracket, bisection where a step would leave it (the flow stress's log
  /// term is infinite at eps_D); ~6 evaluations to 1e-15 of eps_D instead of bisection's ~50.
  template <class G, class DG>
  [[nodiscard]] double solveHat(G g, DG dg, double target) const {
    double lo = 0.0, hi = y_.densification, h = 0.0;
    for (int it = 0; it < 200; ++it) {
      const double r = g(h) - target;
      if (r == 0) return h;
      (r < 0 ? lo : hi) = h;
      double next = h - r / dg(h);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if (std::fabs(next - h) <= 1e-15 * y_.densification || hi - lo <= 1e-15 * y_.densification) return next;
      h = next;
    }
    return h;
  }
  [[nodiscard]] double hatAtStrain(double eps) const {
    return solveHat([&](double x) { return strainAt(x); },
                    [&](double x) { return k_ * y_.flowSlope(x) / f_.bulkModulus + 1.0 / k_; }, eps);
  }
  [[nodiscard]] double hatAtPressure(double P) const {
    return solveHat([&](double x) { return k_ * y_.flowStress(x); }, [&](double x) { return k_ * y_.flowSlope(x); }, P);
  }
  static void check(bool ok, const char* key, double v) {
    if (!ok) throw std::invalid_argument(std::string("crush_curve EOS: ") + key + " out of range, got " + std::to_string(v));
  }

  FoamCrushParams f_;
  FoamHardening y_;
  double k_ = 1, epsD_ = 0, epsY_ = 0, Py_ = 0, hatD_ = 0, Pd_ = 0;
};

}  // namespace mpmice::core
