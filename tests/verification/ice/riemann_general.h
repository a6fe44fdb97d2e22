#pragma once
/// @brief Exact Riemann solver for the 1D Euler equations with any ICE equation of state on each
/// side (ice::Eos: p(rho, e), c^2(rho, e)), for the tests whose materials have no closed-form
/// wave curves (JWL detonation products, Mie-Gruneisen water).
///
/// Each side's wave curve u_K(p) through its state (rho_K, u_K, p_K):
///  - shock (p > p_K): the Hugoniot e = e_K + (p + p_K)(v_K - v) / 2 solved for v at p
///    (bisection on p(1/v, e_H(v)) = p over v in (1e-3 v_K, v_K]); |u - u_K| = sqrt((p - p_K)(v_K - v)),
///    mass flux j = sqrt((p - p_K) / (v_K - v)), shock speed u_K -+ j v_K;
///  - rarefaction (p < p_K): the isentrope de/drho = p / rho^2 and du = -+ c drho / rho, integrated
///    by RK4 in ln rho (kSteps per e-fold) from rho_K down to where p falls below the smallest
///    pressure asked for, tabulated and interpolated linearly in p.
/// p* solves u_L(p) = u_R(p) by bisection. Written here (not taken from the scheme) so the
/// verification compares with an independent answer.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "ice/eos/eos.h"
#include "riemann_exact.h"

namespace mpmice::test {

class GeneralRiemann {
 public:
  GeneralRiemann(Primitive left, const ice::Eos& eosL, Primitive right, const ice::Eos& eosR, double pMin)
      : L_(left, eosL, -1), R_(right, eosR, +1) {
    L_.init(pMin);
    R_.init(pMin);
    double lo = pMin, hi = 1e3 * std::max(left.p, right.p);
    auto g = [&](double p) { return L_.velocity(p) - R_.velocity(p); };  // decreasing in p
    if (!(g(lo) > 0 && g(hi) < 0)) throw std::runtime_error("GeneralRiemann: p* not bracketed (vacuum?)");
    for (int it = 0; it < 200 && hi - lo > 1e-14 * hi; ++it) (g(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
    ps_ = 0.5 * (lo + hi);
    us_ = 0.5 * (L_.velocity(ps_) + R_.velocity(ps_));
  }
  [[nodiscard]] double pStar() const { return ps_; }
  [[nodiscard]] double uStar() const { return us_; }
  /// Speed of side's wave when it is a shock (side < 0 left, > 0 right).
  [[nodiscard]] double shockSpeed(int side) const { return (side < 0 ? L_ : R_).shockSpeed(ps_); }
  /// Density of the star state on side.
  [[nodiscard]] double rhoStar(int side) const { return (side < 0 ? L_ : R_).density(ps_); }

 private:
  struct Side {
    Side(Primitive k, const ice::Eos& law, int side) : K(k), eos(&law), s(side) {}
    Primitive K;
    const ice::Eos* eos;
    int s;  // -1 left, +1 right
    double eK = 0;
    std::vector<double> tp, tu, tr;  // rarefaction table: p (decreasing), u, rho
    static constexpr int kSteps = 4000;

    void init(double pMin) {
      eK = eos->internalEnergy(K.rho, K.p);
      // Isentrope from rho_K downwards in x = ln rho: de/dx = p / rho, du/dx = s c (u rises on the
      // left wave as the density falls: du = -s c drho / rho with s = -1).
      double x = std::log(K.rho), e = eK, u = K.u;
      const double h = -1.0 / kSteps;
      auto rhs = [&](double xx, double ee, double* de, double* du) {
        const double rho = std::exp(xx);
        const double p = eos->pressure(rho, ee), c2 = eos->soundSpeed2(rho, ee);
        *de = p / rho;
        *du = s * std::sqrt(std::max(c2, 0.0));
      };
      tp = {K.p};
      tu = {K.u};
      tr = {K.rho};
      for (int n = 0; n < 60 * kSteps && tp.back() > pMin; ++n) {
        double e1, u1, e2, u2, e3, u3, e4, u4;
        rhs(x, e, &e1, &u1);
        rhs(x + 0.5 * h, e + 0.5 * h * e1, &e2, &u2);
        rhs(x + 0.5 * h, e + 0.5 * h * e2, &e3, &u3);
        rhs(x + h, e + h * e3, &e4, &u4);
        e += h / 6 * (e1 + 2 * e2 + 2 * e3 + e4);
        u += h / 6 * (u1 + 2 * u2 + 2 * u3 + u4);
        x += h;
        tp.push_back(eos->pressure(std::exp(x), e));
        tu.push_back(u);
        tr.push_back(std::exp(x));
      }
      if (tp.back() > pMin) throw std::runtime_error("GeneralRiemann: isentrope does not reach pMin");
    }
    // Hugoniot specific volume at p > p_K.
    [[nodiscard]] double hugoniotVolume(double p) const {
      const double vK = 1.0 / K.rho;
      double lo = 1e-3 * vK, hi = vK;  // p_H(v) decreases with v
      for (int it = 0; it < 200; ++it) {
        const double v = 0.5 * (lo + hi);
        const double e = eK + 0.5 * (p + K.p) * (vK - v);
        (eos->pressure(1.0 / v, e) > p ? lo : hi) = v;
      }
      return 0.5 * (lo + hi);
    }
    [[nodiscard]] double rarefaction(double p, const std::vector<double>& q) const {
      const auto it = std::lower_bound(tp.rbegin(), tp.rend(), p);  // tp decreasing: search reversed
      const std::size_t j = static_cast<std::size_t>(tp.rend() - it);  // tp[j-1] >= p > tp[j]... clamp
      const std::size_t b = std::clamp<std::size_t>(j, 1, tp.size() - 1), a = b - 1;
      const double w = (p - tp[a]) / (tp[b] - tp[a]);
      return q[a] + w * (q[b] - q[a]);
    }
    [[nodiscard]] double velocity(double p) const {
      if (p > K.p) {
        const double v = hugoniotVolume(p);
        return K.u + s * std::sqrt((p - K.p) * (1.0 / K.rho - v));
      }
      return rarefaction(p, tu);
    }
    [[nodiscard]] double density(double p) const { return p > K.p ? 1.0 / hugoniotVolume(p) : rarefaction(p, tr); }
    [[nodiscard]] double shockSpeed(double p) const {
      const double vK = 1.0 / K.rho, v = hugoniotVolume(p);
      return K.u + s * std::sqrt((p - K.p) / (vK - v)) * vK;
    }
  };
  Side L_, R_;
  double ps_ = 0, us_ = 0;
};

}  // namespace mpmice::test
