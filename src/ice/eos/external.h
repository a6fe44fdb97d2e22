#pragma once
/// @brief EOS of external (solid) materials: the solid_bulk law of src/core/material (scene name
/// `solid_bulk`; `bulk_modulus`, `threshold_pressure`, `reference_density`). Pressure depends on
/// density only; the supplied temperature gives e = cv T. p <= 0 lies below its range.
#include "ice/eos/eos.h"
#include "ice/ice_constants.h"
#include "core/material/solid_bulk_eos.h"

namespace mpmice::ice {

class ExternalSolidEos final : public Eos {
 public:
  ExternalSolidEos(const core::SolidBulkEos& law, double cv) : Eos(cv), law_(law) {}
  [[nodiscard]] const char* name() const override { return "solid_bulk"; }
  void pressure(std::size_t n, const double* rho, const double* e, double* p) const override {
    (void)e;
    for (std::size_t i = 0; i < n; ++i) p[i] = law_.pressure(rho[i]);
  }
  void density(std::size_t n, const double* p, const double* e, double* rho, double* drhodp) const override {
    (void)e;
    for (std::size_t i = 0; i < n; ++i) {
      rho[i] = law_.density(p[i]);
      drhodp[i] = rho[i] > 0 ? 1.0 / law_.dpdrho(rho[i]) : 0.0;
    }
  }
  /// No state at p <= 0 (the tension branch's density tends to 0 there): the floor is 0.
  void pressureFloor(std::size_t n, const double* e, double* pmin) const override {
    (void)e;
    for (std::size_t i = 0; i < n; ++i) pmin[i] = 0.0;
  }
  void soundSpeed2(std::size_t n, const double* rho, const double* e, double* c2) const override {
    (void)e;
    for (std::size_t i = 0; i < n; ++i) c2[i] = law_.dpdrho(rho[i]);
  }
  /// No caloric relation: the supplied temperature sets e; here e = cv * kReferenceTemperature.
  [[nodiscard]] double internalEnergy(double, double) const override { return cv() * kReferenceTemperature; }
  [[nodiscard]] const core::SolidBulkEos& law() const { return law_; }

 private:
  core::SolidBulkEos law_;
};

}  // namespace mpmice::ice
