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

}  // namespace mpmice::study
