#pragma once
/// @brief J2 (von Mises) elastic-plastic solid: hypoelastic Jaumann trial stress, radial return,
/// isotropic hardening (linear or piecewise linear), optional failure strain.
///
/// Yield stress sigma_y(eps_p) = yield_stress + hardening_modulus eps_p, or interpolated in the
/// tables "plastic_strain"/"stress" when given (extrapolated with the last slope). Once the
/// equivalent plastic strain reaches failure_strain (> 0), the particle fails: it keeps only a
/// compressive pressure (no shear, no tension). Scene: `constitutive: {type: j2_plasticity,
/// youngs_modulus, poissons_ratio, yield_stress, hardening_modulus, failure_strain}`.
///
/// Rate dependence (scene name cowper_symonds, with rate_c and rate_p): the flow stress is
/// scaled by the Cowper-Symonds factor 1 + (rate / C)^(1/p), rate = sqrt(2/3 D':D') the
/// equivalent (total) strain rate of the step, as LS-DYNA's *MAT_PIECEWISE_LINEAR_PLASTICITY
/// with VP = 0.
#include <vector>

#include "mpm/material/constitutive_model.h"

namespace mpmice::mpm {

class J2Plasticity final : public ElasticWaveModel {
 public:
  J2Plasticity(const ElasticConstants& c, double yieldStress, double hardening,
               double failureStrain, std::vector<double> tableStrain = {},
               std::vector<double> tableStress = {});
  [[nodiscard]] const char* name() const override { return rateC_ > 0 ? "cowper_symonds" : "j2_plasticity"; }
  [[nodiscard]] bool plasticHistory() const override { return true; }
  /// Cowper-Symonds scaling of the flow stress (C [1/s] > 0, p > 0).
  void setRateDependence(double c, double p);
  void updateStress(ParticleSet& p, std::size_t begin, std::size_t end, double dt) const override;
  /// Yield stress and its slope at equivalent plastic strain e, times the rate factor.
  void yield(double e, double& sy, double& slope, double rateFactor = 1.0) const;

 private:
  double sy0_, H_, failure_;
  std::vector<double> te_, ts_;
  double rateC_ = 0, rateP_ = 1;  // Cowper-Symonds; C = 0: rate-independent
};

}  // namespace mpmice::mpm
