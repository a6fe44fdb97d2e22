#pragma once
/// @brief Linear elasticity in rate form with the Jaumann (objective) stress rate.
///
///     sigma_new = sigma + dt (lambda tr(D) I + 2 G D + W sigma - sigma W),  D = sym L, W = skew L
///
/// Scene: `constitutive: {type: linear_elastic, youngs_modulus, poissons_ratio}` (or bulk_modulus
/// and shear_modulus). Small strains; rotations handled objectively.
#include "mpm/material/constitutive_model.h"

namespace mpmice::mpm {

class LinearElastic final : public ElasticWaveModel {
 public:
  explicit LinearElastic(const ElasticConstants& c) : ElasticWaveModel(c) {}
  [[nodiscard]] const char* name() const override { return "linear_elastic"; }
  void updateStress(ParticleSet& p, std::size_t begin, std::size_t end, double dt) const override;

 private:
  /// updateStress in 1D / 2D (out-of-plane components not stored): the same bits, fewer operations.
  void updatePlanar(ParticleSet& p, std::size_t begin, std::size_t end, double dt) const;
};

}  // namespace mpmice::mpm
