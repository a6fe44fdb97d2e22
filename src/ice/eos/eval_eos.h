#pragma once
/// @brief Base of the EOS given by one pointwise evaluation (mie_gruneisen, jwl): the batch calls
/// from Derived's p(rho, e) and dp/drho at fixed e, so each law writes only its own formulas.
///
/// Derived provides eval(rho, e, &p, &dpdrho), densityGuess(p, e) (the start of the Newton
/// inversion of invertPressure), maxDensity() (the end of its density range) and soundSpeed2At(rho, p, dpdrho) (c^2 from the evaluated p and
/// its slope). density() returns the derivative at the root (1 / dp/drho, 0 where the slope is not
/// positive).
#include "ice/eos/eos.h"

namespace mpmice::ice {

template <class Derived>
class EvalEos : public Eos {
 public:
  using Eos::Eos;
  void pressure(std::size_t n, const double* rho, const double* e, double* p) const final {
    for (std::size_t i = 0; i < n; ++i) {
      double dp;
      self().eval(rho[i], e[i], &p[i], &dp);
    }
  }
  void density(std::size_t n, const double* p, const double* e, double* rho, double* drhodp) const final {
    for (std::size_t i = 0; i < n; ++i) {
      const double ei = e[i];
      const double r = invertPressure(p[i], self().densityGuess(p[i], ei),
                                      [&](double x, double* pp, double* dd) { self().eval(x, ei, pp, dd); },
                                      self().maxDensity());
      double pp, dd;
      self().eval(r, ei, &pp, &dd);
      rho[i] = r;
      drhodp[i] = dd > 0 ? 1.0 / dd : 0.0;
    }
  }
  void soundSpeed2(std::size_t n, const double* rho, const double* e, double* c2) const final {
    for (std::size_t i = 0; i < n; ++i) {
      double p, dp;
      self().eval(rho[i], e[i], &p, &dp);
      c2[i] = self().soundSpeed2At(rho[i], p, dp);
    }
  }

 private:
  [[nodiscard]] const Derived& self() const { return static_cast<const Derived&>(*this); }
};

}  // namespace mpmice::ice
