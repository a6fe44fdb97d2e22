#pragma once
/// @brief The seed's validation measure (Eq. 13) of a finished pressurized-cylinder run: the
/// particle average of |(sigma_r + sigma_theta) - S| / S against the exact Lame sum. Used by
/// benchmarks/coupled/cylinder_lame (which prints it) and by the study tool's `lame_cylinder`
/// reference.
#include <string>
#include <vector>

#include "study/reference/output_files.h"

namespace mpmice::core {
struct Scene;
}

namespace mpmice::study {

/// What the exact solution needs from the scene.
struct Annulus {
  double ri = 0.5, ro = 1.0, pAmbient = 0, pRef = 0;  // legacy: the seed, absolute pressure
  bool fromScene = false;
  std::vector<std::string> fluids{"air"};  // the fluid materials (output fields <fluid>_density)
};

/// The radii from the solid's annulus, p_amb from the outflow boundary pressure (else the fluid
/// region outside the annulus), p_ref from the solid's EOS threshold_pressure. Throws naming the
/// file when the scene has no solid annulus or no ambient pressure.
Annulus annulusFromScene(const std::string& sceneFile);
/// The same from a scene in memory (`file` names it in the errors).
Annulus annulusOf(const core::Scene& scene, const std::string& file);

/// The exact Lame sum sigma_r + sigma_theta = 2 ((P - p_ref) r_i^2 - (p_amb - p_ref) r_o^2) /
/// (r_o^2 - r_i^2) (stress from the stress-free reference at p_ref), P the inner pressure.
double lameSum(const Annulus& annulus, double P);

/// Everything the measure computes.
struct LameError {
  std::string particlesFile;
  int step = 0;
  double time = 0, dx = 0;
  std::size_t particles = 0, bandParticles = 0;
  double P = 0;         // mean pressure of the cells with r < 0.8 r_i [Pa]
  double A = 0, B = 0;  // Lame: sigma_r = A - B / r^2, sigma_theta = A + B / r^2
  double sum = 0;       // the exact sum S = 2 A
  double error = 0;     // Eq. 13
  double bandError = 0, coreError = 0;  // summed over the band within one cell of a surface / the interior
  std::vector<double> x, stress;        // positions (n x 3) and stresses (n x sc) of the last step
  std::size_t stressComponents = 0;
};

/// Eq. 13 of the run whose output is `<dir>/<scene>_...h5`, with the annulus `geo`. Throws when
/// the run left no output (or no cell inside 0.8 r_i).
LameError lameError(const std::string& dir, const std::string& scene, const Annulus& geo);

/// How much of the gas inside the inner radius got out through the wall: the fluids' mass in the
/// cells whose centre lies inside r_i, at the first and at the last output step, and in the
/// wall's cells (r_i <= r < r_o). The heating adds no mass and the wall's strain moves r_i by
/// ~1e-4 of a cell, so what the inside loses left through (or into) the wall.
struct GasLeak {
  std::string firstGrid, lastGrid;
  int firstStep = 0, lastStep = 0;
  double firstTime = 0, lastTime = 0;
  double inside0 = 0, inside = 0;  // fluid mass inside r_i [kg per unit depth in 2D]
  double wall0 = 0, wall = 0;      // fluid mass in the wall's cells
  /// (inside0 - inside) / inside0: the leak fraction.
  [[nodiscard]] double fraction() const { return inside0 > 0 ? (inside0 - inside) / inside0 : 0.0; }
};

/// The gas leak of the run whose output is `<dir>/<scene>_...h5` (first and last output step).
/// Throws when the run left no output, a fluid's density field is missing, or no cell centre lies
/// inside r_i.
GasLeak gasLeak(const std::string& dir, const std::string& scene, const Annulus& geo);

}  // namespace mpmice::study
