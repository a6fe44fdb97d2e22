#pragma once
/// @brief The adiabatic piston's exact answer (configs/piston.yaml, Uintah's pistonVal): a free
/// solid piston between two columns of ideal gas trapped by walls, the gas in the quasi-static
/// state,
///   s' = v,  (M + m_gas / 3) v' = -(p - p_L),  p = p0 (h0 / (h0 - s))^gamma,  p_L = p0 (hL0 / (hL0 + s))^gamma,
/// integrated by RK4 to round-off; and the measure of a finished run against it (the study's
/// `piston` reference). Quasi-static: the gas's velocity is linear between wall and piston, its
/// inertia is a third of its mass moving with the piston (Rayleigh's correction; m_gas =
/// rho_gas (h0 + hL0)). Exact in the limit of a large density ratio; at a ratio of 10 within
/// 0.02 % of a Lagrangian solution of the gas to 20 ms, at a ratio of 1 within 0.8 % (a model
/// there, not the exact answer; docs/stability.md).
#include <string>

#include "core/scene/scene.h"

namespace mpmice::study {

/// What the exact answer needs, read from the scene: the one solid region (the piston) and the
/// gas (the first fluid region's pressure, the fluid material's ideal-gas gamma).
struct PistonSetup {
  double p0 = 0, gamma = 0, hL0 = 0, h0 = 0, M = 0, v0 = 0, xLo = 0, xHi = 0;
  double gasMass = 0;  // both gas columns' mass per unit area (their inertia: M + gasMass / 3)
  std::string gas;  // the fluid material's name
};

/// Throws naming the file when the scene is not a 1D piston (no solid region, no ideal gas).
PistonSetup pistonSetup(const core::Scene& s);

/// The exact state at t: displacement s, velocity v and the two gas pressures.
struct PistonExact {
  double s = 0, v = 0, p = 0, pL = 0;
};
PistonExact pistonExact(const PistonSetup& e, double t);

/// A finished run measured at its last output: the piston's displacement (mass-weighted particle
/// mean, last output against the first) and the mean pressure of the trapped gas's pure cells
/// (volume fraction > 0.999, ahead of the displaced piston).
struct PistonError {
  double time = 0, s = 0, p = 0;
  PistonExact exact;
  double pressureError = 0;      // |p / p_exact - 1|
  double displacementError = 0;  // |s / s_exact - 1|
};
PistonError pistonError(const std::string& dir, const std::string& scene, const std::string& sceneFile);

}  // namespace mpmice::study
