#pragma once
/// @brief Compressible neo-Hookean hyperelasticity (Simo & Hughes form), large deformations.
///
///     sigma = G/J (b - I) + lambda ln(J)/J I,   b = F F^T, J = det F, lambda = K - 2G/3
///
/// Scene: `constitutive: {type: neo_hookean, youngs_modulus, poissons_ratio}` (or bulk_modulus
/// and shear_modulus). Reduces to linear elasticity for small strains.
#include "mpm/material/constitutive_model.h"

namespace mpmice::mpm {

class NeoHookean final : public ElasticWaveModel {
 public:
  explicit NeoHookean(const ElasticConstants& c) : ElasticWaveModel(c) {}
  [[nodiscard]] const char* name() const override { return "neo_hookean"; }
  void updateStress(ParticleSet& p, std::size_t begin, std::size_t end, double dt) const override;
};

}  // namespace mpmice::mpm
