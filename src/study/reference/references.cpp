#include "study/reference/references.h"

#include <vector>

#include "study/reference/lame_cylinder.h"
#include "study/reference/piston.h"
#include "study/reference/probe_curve.h"
#include "study/reference/shock_slab.h"

namespace mpmice::study {

namespace {

const std::vector<Reference>& registry() {
  static const std::vector<Reference> refs{
      {"lame_cylinder",
       "Eq. 13: the particle mean of |(sigma_r + sigma_theta) - S| / S against the exact Lame sum of the "
       "scene's solid annulus (benchmarks/coupled/cylinder_lame)",
       [](const RunFiles& r) { return lameError(r.dir, r.name, annulusFromScene(r.scene)).error; }},
      {"piston",
       "|p / p_exact - 1| of the trapped gas's pure cells at the last output against the free piston's "
       "quasi-static adiabat (configs/piston.yaml; exact for a large solid-to-gas density ratio)",
       [](const RunFiles& r) { return pistonError(r.dir, r.name, r.scene).pressureError; }},
      {"shock_slab",
       "|p / p5 - 1| of the reflected plateau's mean pressure at the last output against the rigid-wall "
       "reflection of the scene's shock (configs/shock_slab.yaml; exact for a large solid-to-gas impedance ratio)",
       [](const RunFiles& r) { return slabPressureError(r.dir, r.name, r.scene); }},
      {"probe_curve",
       "rms(u_run - u_ref) / rms(u_ref) of the probe column `reference_column` of the run's <scene>_probes.csv against "
       "the curve `reference_curve`, on the curve's samples inside the run's time span (the flap's tip against "
       "MPM + OpenFOAM)",
       [](const RunFiles& r) { return probeCurveError(r); }, true},
  };
  return refs;
}

}  // namespace

const Reference& findReference(const std::string& name) {
  for (const auto& r : registry())
    if (r.name == name) return r;
  throw std::invalid_argument("'" + name + "' is not a reference (valid: " + referenceNames() + ")");
}

std::string referenceNames() {
  std::string s;
  for (const auto& r : registry()) s += (s.empty() ? "" : ", ") + r.name;
  return s;
}

}  // namespace mpmice::study
