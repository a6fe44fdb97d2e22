#pragma once
/// @brief The shock on a steel slab's exact answers (configs/shock_slab.yaml): a shock in ideal
/// gas (the regions `shocked`, behind it, and `quiet`, ahead of it) reflected from a solid slab
/// (the region `slab`) whose acoustic impedance is far above the gas's, i.e. from a rigid wall;
/// the reflected pressure p5 from the shock relation that brings the gas behind the incident
/// shock to rest, u2 = (p5 - p2) sqrt(A / (p5 + B)), A = 2 / ((gamma + 1) rho2),
/// B = (gamma - 1) p2 / (gamma + 1); the slab's longitudinal speed sqrt((K + 4G/3) / rho). And the
/// measure of a finished run against it (the study's `shock_slab` reference): the mean pressure
/// of the reflected plateau. Rigid means Z_solid >> Z_gas: the interface moves at about
/// p5 / Z_solid against the gas's u2, so the answer's own error is ~p5 / (Z_solid u2) (3e-5 for
/// steel; 5 % at a density ratio of 10 with the steel's wave speed kept).
#include <string>

#include "core/scene/scene.h"

namespace mpmice::study {

struct SlabExact {
  double gamma = 0, p1 = 0, p2 = 0, p5 = 0, W = 0, Wr = 0, xShock = 0, xWall = 0, cSolid = 0;
  std::string gas;
  [[nodiscard]] double hitTime() const { return (xWall - xShock) / W; }
};

/// Throws naming the file when a region or a key is missing.
SlabExact slabExact(const core::Scene& s);

/// The reflected plateau at time t: the pure-gas cells (volume fraction > 0.999) from a quarter
/// of the way behind the reflected shock to two cells off the slab.
struct Plateau {
  double mean = 0, min = 0, max = 0;
  int cells = 0;
};
/// x: cell centres; p, theta: the cells' pressure and the gas's volume fraction.
Plateau reflectedPlateau(const SlabExact& e, double t, double dx, const double* x, const double* p,
                         const double* theta, int n);

/// |plateau mean / p5 - 1| at the last output of the run in `dir`; throws when the run ended
/// before the reflected plateau is six cells wide.
double slabPressureError(const std::string& dir, const std::string& scene, const std::string& sceneFile);

}  // namespace mpmice::study
