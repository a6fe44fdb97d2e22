#pragma once
/// @brief Stiffened gas (scene name `stiffened_gas`, parameters `gamma`, `p_inf`):
/// p = (gamma - 1) rho e - gamma p_inf, c^2 = gamma (p + p_inf) / rho, e = cv T + p_inf / rho;
/// admissible: p > -p_inf.
#include <limits>

#include "ice/eos/eos.h"

namespace mpmice::ice {

class StiffenedGas final : public Eos {
 public:
  StiffenedGas(double gamma, double pInf, double cv) : Eos(cv), g_(gamma), pinf_(pInf) {}
  [[nodiscard]] const char* name() const override { return "stiffened_gas"; }
  void pressure(std::size_t n, const double* rho, const double* e, double* p) const override {
    const double gm1 = g_ - 1.0, gp = g_ * pinf_;
    for (std::size_t i = 0; i < n; ++i) p[i] = gm1 * rho[i] * e[i] - gp;
  }
  void density(std::size_t n, const double* p, const double* e, double* rho, double* drhodp) const override {
    const double gm1 = g_ - 1.0, gp = g_ * pinf_;
    for (std::size_t i = 0; i < n; ++i) {
      const double a = 1.0 / (gm1 * e[i]);
      rho[i] = (p[i] + gp) * a;
      drhodp[i] = a;
    }
  }
  void soundSpeed2(std::size_t n, const double* rho, const double* e, double* c2) const override {
    const double k = g_ * (g_ - 1.0);
    for (std::size_t i = 0; i < n; ++i) c2[i] = k * (e[i] - pinf_ / rho[i]);
  }
  /// T > 0 and c^2 = gamma (p + p_inf) / rho > 0 need p > -p_inf (then rho >= p_inf / e > 0);
  /// e <= 0 admits no state.
  void pressureFloor(std::size_t n, const double* e, double* pmin) const override {
    for (std::size_t i = 0; i < n; ++i) pmin[i] = e[i] > 0 ? -pinf_ : std::numeric_limits<double>::infinity();
  }
  [[nodiscard]] double internalEnergy(double rho, double p) const override {
    return (p + g_ * pinf_) / ((g_ - 1.0) * rho);
  }
  [[nodiscard]] double coldEnergy(double rho) const override { return pinf_ / rho; }
  [[nodiscard]] bool hasColdEnergy() const override { return pinf_ != 0.0; }
  [[nodiscard]] double gamma() const { return g_; }
  [[nodiscard]] double pInf() const { return pinf_; }

 private:
  double g_, pinf_;
};

}  // namespace mpmice::ice
