#pragma once
/// @brief Crushable foam (Deshpande & Fleck 2000, isotropic hardening; the form of LS-DYNA's
/// *MAT_DESHPANDE_FLECK_FOAM): a homogenized metal foam that yields under pressure as well as
/// shear and hardens to densification.
///
/// Yield surface  sigma_hat = Y(eps_hat),  sigma_hat^2 = (q^2 + alpha^2 sigma_m^2) / (1 + (alpha/3)^2),
/// q the von Mises stress, sigma_m the mean stress; alpha^2 = 9 (1 - 2 nu_p) / (2 (1 + nu_p)) from the
/// plastic Poisson's ratio nu_p (0: alpha = 2.12, no lateral plastic flow in uniaxial crush).
/// Hardening  Y = sigma_p + gamma eps_hat / eps_D + alpha_2 ln(1 / (1 - (eps_hat / eps_D)^beta)):
/// plateau, linear rise and densification (Y -> infinity as eps_hat -> eps_D). Associated flow;
/// eps_hat is the plastic strain work-conjugate to sigma_hat (sigma_hat d eps_hat = sigma : d eps_p).
/// Hypoelastic (Jaumann) trial with K, G; the return solves the one scalar equation of the
/// consistency condition for the multiplier by safeguarded Newton (bracketed below eps_D).
/// Closed forms (verified in tests/unit/mpm/test_constitutive.cpp): uniaxial stress |sigma| =
/// Y(|eps| - |sigma|/E); hydrostatic |sigma_m| = Y(eps_hat) sqrt(1 + alpha^2/9) / alpha with
/// eps_hat = (|eps_v| - |sigma_m|/K) sqrt(1 + alpha^2/9) / alpha.
/// Compaction to the solid (lock-up): eps_D is the crush that takes the foam to its cell walls'
/// density, eps_D = -(9 + alpha^2)/(3 alpha^2) ln(rho_foam / rho_solid) (LS-DYNA's definition), so
/// the foam is fully dense at the volume ratio J_d = rho_foam / rho_solid = exp(-3 alpha^2 eps_D /
/// (9 + alpha^2)); uniaxial crush reaches it at eps_hat = eps_D, where Y is infinite. Other paths
/// reach J_d with Y finite (hydrostatic crush at eps_hat = eps_D sqrt(1 + alpha^2/9) / alpha ...),
/// and the surface alone let a confined foam under a water shock compact to J = 0.012, denser than
/// aluminium. At J = V / V0 <= J_d the particle is the compacted solid: its mean stress elastic
/// with the solid's bulk modulus K_s (`densified_bulk_modulus`; no further volumetric plastic flow),
/// its deviator elastic with G and bounded by the flow stress it reached (J2 radial return), and
/// its CFL wave speed sqrt((K_s + 4 G / 3) / rho). A step that crosses J_d is split there (its
/// volumetric strain tr D dt). Closed form past J_d (hydrostatic): p = p(J_d) + K_s ln(J_d / J).
/// Scene: `model: {type: crushable_foam, youngs_modulus, poissons_ratio, plateau_stress,
/// densification_strain, densified_bulk_modulus, plastic_poissons_ratio, hardening_gamma,
/// hardening_alpha2, hardening_beta}`.
#include "core/material/foam_crush_curve.h"
#include "mpm/material/constitutive_model.h"
#include "mpm/material/tensor.h"

namespace mpmice::mpm {

/// The foam's hardening and compacted solid (the crushable_foam keys), shared with ICE's view of the
/// foam (core/material/foam_crush_curve.h: the crush_curve EOS).
using CrushableFoamParams = core::FoamHardening;

class CrushableFoam final : public ConstitutiveModel {
 public:
  CrushableFoam(const ElasticConstants& c, const CrushableFoamParams& f);
  [[nodiscard]] const char* name() const override { return "crushable_foam"; }
  [[nodiscard]] bool plasticHistory() const override { return true; }
  void updateStress(ParticleSet& p, std::size_t begin, std::size_t end, double dt) const override;
  /// The uncompacted foam's P-wave speed (the model does not know the density it starts at; the
  /// step's signal speed, maxSignalSpeed, takes each particle's own state).
  [[nodiscard]] double waveSpeed(double rho) const override { return c_.pWaveSpeed(rho); }
  /// max over particles of sqrt(M / (m / V)) + |v|, M = K + 4 G / 3, or K_s + 4 G / 3 once compacted.
  [[nodiscard]] double maxSignalSpeed(const ParticleSet& p, std::size_t begin, std::size_t end, int dim,
                                      std::size_t* arg = nullptr) const override;
  /// The volume ratio V / V0 at which the foam is fully dense.
  [[nodiscard]] double denseVolumeRatio() const { return denseJ_; }
  /// Flow stress Y at eps_hat (< eps_D).
  [[nodiscard]] double flowStress(double epsHat) const;
  /// The yield surface's shape factor alpha.
  [[nodiscard]] double alpha() const { return alpha_; }

 private:
  /// One step of the foam's law (Deshpande-Fleck return) and of the compacted solid's, from stress
  /// s over dt with velocity gradient L; *eqps in and out.
  [[nodiscard]] Sym3 foamUpdate(const Mat3& L, const Sym3& s, double dt, double* eqps) const;
  [[nodiscard]] Sym3 denseUpdate(const Mat3& L, const Sym3& s, double dt, double* eqps) const;

  ElasticConstants c_;
  CrushableFoamParams f_;
  double alpha_ = 0, shape_ = 1;  // shape_ = 1 + (alpha/3)^2
  double denseJ_ = 0;             // J_d
};

}  // namespace mpmice::mpm
