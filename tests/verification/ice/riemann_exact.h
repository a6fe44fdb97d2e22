#pragma once
/// @brief Exact Riemann solver for the 1D Euler equations with ideal or stiffened gases on each
/// side (Toro, "Riemann Solvers and Numerical Methods for Fluid Dynamics", ch. 4, with
/// p -> p + p_inf for a stiffened gas). Written here so the verification tests compute their
/// reference solutions instead of reading tables.
#include <cmath>
#include <stdexcept>

namespace mpmice::test {

struct Primitive {
  double rho, u, p;
};

struct GasLaw {
  double gamma = 1.4, pinf = 0.0;
};

class ExactRiemann {
 public:
  ExactRiemann(Primitive left, Primitive right, GasLaw gl = {}, GasLaw gr = {})
      : L_(left), R_(right), gl_(gl), gr_(gr) {
    cL_ = std::sqrt(gl_.gamma * (L_.p + gl_.pinf) / L_.rho);
    cR_ = std::sqrt(gr_.gamma * (R_.p + gr_.pinf) / R_.rho);
    solveStar();
  }
  [[nodiscard]] double pStar() const { return ps_; }
  [[nodiscard]] double uStar() const { return us_; }

  /// State at similarity coordinate xi = (x - x0) / t.
  [[nodiscard]] Primitive sample(double xi) const {
    if (xi <= us_) return sampleSide(L_, gl_, cL_, xi, -1.0);
    return sampleSide(R_, gr_, cR_, xi, +1.0);
  }
  /// Density of the star region on the left (side < 0) or right.
  [[nodiscard]] double rhoStar(int side) const {
    const Primitive& K = side < 0 ? L_ : R_;
    const GasLaw& g = side < 0 ? gl_ : gr_;
    const double pk = K.p + g.pinf, pb = ps_ + g.pinf, gm = (g.gamma - 1) / (g.gamma + 1);
    if (ps_ > K.p) return K.rho * (pb / pk + gm) / (gm * pb / pk + 1.0);
    return K.rho * std::pow(pb / pk, 1.0 / g.gamma);
  }
  /// Shock speed on side (< 0 left, > 0 right); only meaningful where that wave is a shock.
  [[nodiscard]] double shockSpeed(int side) const {
    const Primitive& K = side < 0 ? L_ : R_;
    const GasLaw& g = side < 0 ? gl_ : gr_;
    const double c = side < 0 ? cL_ : cR_;
    const double q = std::sqrt((g.gamma + 1) / (2 * g.gamma) * (ps_ + g.pinf) / (K.p + g.pinf) +
                               (g.gamma - 1) / (2 * g.gamma));
    return side < 0 ? K.u - c * q : K.u + c * q;
  }

 private:
  // f_K(p) and its derivative.
  void f(const Primitive& K, const GasLaw& g, double c, double p, double* fv, double* df) const {
    const double pb = p + g.pinf, pk = K.p + g.pinf;
    if (p > K.p) {
      const double A = 2.0 / ((g.gamma + 1) * K.rho), B = (g.gamma - 1) / (g.gamma + 1) * pk;
      const double q = std::sqrt(A / (pb + B));
      *fv = (p - K.p) * q;
      *df = q * (1.0 - 0.5 * (p - K.p) / (pb + B));
    } else {
      const double e = (g.gamma - 1) / (2 * g.gamma);
      *fv = 2 * c / (g.gamma - 1) * (std::pow(pb / pk, e) - 1.0);
      *df = 1.0 / (K.rho * c) * std::pow(pb / pk, -(g.gamma + 1) / (2 * g.gamma));
    }
  }
  void solveStar() {
    const double du = R_.u - L_.u;
    double p = std::max(0.5 * (L_.p + R_.p), 1e-8 * std::max(L_.p, R_.p));
    const double pmin = std::max(-gl_.pinf, -gr_.pinf);
    for (int it = 0; it < 200; ++it) {
      double fl, dl, fr, dr;
      f(L_, gl_, cL_, p, &fl, &dl);
      f(R_, gr_, cR_, p, &fr, &dr);
      double pn = p - (fl + fr + du) / (dl + dr);
      if (pn <= pmin) pn = 0.5 * (p + pmin) + 1e-300;
      if (std::abs(pn - p) <= 1e-15 * (std::abs(pn) + std::abs(p))) {
        p = pn;
        break;
      }
      p = pn;
    }
    double fl, dl, fr, dr;
    f(L_, gl_, cL_, p, &fl, &dl);
    f(R_, gr_, cR_, p, &fr, &dr);
    ps_ = p;
    us_ = 0.5 * (L_.u + R_.u) + 0.5 * (fr - fl);
  }
  // side = -1: left of the contact; +1 right (signs mirror Toro's formulas).
  [[nodiscard]] Primitive sampleSide(const Primitive& K, const GasLaw& g, double c, double xi, double side) const {
    const double G = g.gamma, pb = ps_ + g.pinf, pk = K.p + g.pinf;
    const int sd = side < 0 ? -1 : 1;
    if (ps_ > K.p) {  // shock
      const double S = shockSpeed(sd);
      if ((side < 0 && xi <= S) || (side > 0 && xi >= S)) return K;
      return {rhoStar(sd), us_, ps_};
    }
    const double cs = c * std::pow(pb / pk, (G - 1) / (2 * G));
    const double head = side < 0 ? K.u - c : K.u + c;
    const double tail = side < 0 ? us_ - cs : us_ + cs;
    if ((side < 0 && xi <= head) || (side > 0 && xi >= head)) return K;
    if ((side < 0 && xi >= tail) || (side > 0 && xi <= tail)) return {rhoStar(sd), us_, ps_};
    const double a = 2 / (G + 1) - side * (G - 1) / ((G + 1) * c) * (K.u - xi);
    const double rho = K.rho * std::pow(a, 2 / (G - 1));
    const double u = 2 / (G + 1) * (-side * c + (G - 1) / 2 * K.u + xi);
    const double p = pk * std::pow(a, 2 * G / (G - 1)) - g.pinf;
    return {rho, u, p};
  }

  Primitive L_, R_;
  GasLaw gl_, gr_;
  double cL_, cR_, ps_ = 0, us_ = 0;
};

}  // namespace mpmice::test
