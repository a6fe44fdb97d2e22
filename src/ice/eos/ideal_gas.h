#pragma once
/// @brief Ideal gas (scene name `ideal_gas`, parameter `gamma`): p = (gamma - 1) rho e, e = cv T.
#include <limits>

#include "ice/eos/eos.h"

namespace mpmice::ice {

class IdealGas final : public Eos {
 public:
  IdealGas(double gamma, double cv) : Eos(cv), g_(gamma) {}
  [[nodiscard]] const char* name() const override { return "ideal_gas"; }
  void pressure(std::size_t n, const double* rho, const double* e, double* p) const override {
    const double gm1 = g_ - 1.0;
    for (std::size_t i = 0; i < n; ++i) p[i] = gm1 * rho[i] * e[i];
  }
  void density(std::size_t n, const double* p, const double* e, double* rho, double* drhodp) const override {
    const double gm1 = g_ - 1.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double a = 1.0 / (gm1 * e[i]);
      rho[i] = p[i] * a;
      drhodp[i] = a;
    }
  }
  void soundSpeed2(std::size_t n, const double* rho, const double* e, double* c2) const override {
    (void)rho;
    const double k = g_ * (g_ - 1.0);
    for (std::size_t i = 0; i < n; ++i) c2[i] = k * e[i];
  }
  /// p > 0 (rho > 0) and e > 0 (T > 0): no admissible state at e <= 0.
  void pressureFloor(std::size_t n, const double* e, double* pmin) const override {
    for (std::size_t i = 0; i < n; ++i) pmin[i] = e[i] > 0 ? 0.0 : std::numeric_limits<double>::infinity();
  }
  [[nodiscard]] double internalEnergy(double rho, double p) const override { return p / ((g_ - 1.0) * rho); }
  [[nodiscard]] double gamma() const { return g_; }

 private:
  double g_;
};

}  // namespace mpmice::ice
