#pragma once
/// @brief EOS of external (solid) materials: a barotropic law of src/core/material, the solid_bulk
/// law (scene name `solid_bulk`; `bulk_modulus`, `threshold_pressure`, `reference_density`) or a
/// crushable foam's crush curve (`crush_curve`, the crushable_foam model's keys). Pressure depends
/// on density only; the supplied temperature gives e = cv T. p <= 0 lies below its range.
#include "core/material/foam_crush_curve.h"
#include "core/material/solid_bulk_eos.h"
#include "ice/eos/eos.h"
#include "ice/ice_constants.h"

namespace mpmice::ice {

/// Law: pressure(rho), dpdrho(rho), density(p) (0 where p is below its range).
template <class Law>
class ExternalSolidEos final : public Eos {
 public:
  ExternalSolidEos(const Law& law, const char* name, double cv) : Eos(cv), law_(law), name_(name) {}
  [[nodiscard]] const char* name() const override { return name_; }
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
  [[nodiscard]] const Law& law() const { return law_; }

 private:
  Law law_;
  const char* name_;
};

}  // namespace mpmice::ice
