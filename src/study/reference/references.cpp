#include "study/reference/references.h"

#include <vector>

#include "study/reference/lame_cylinder.h"

namespace mpmice::study {

namespace {

const std::vector<Reference>& registry() {
  static const std::vector<Reference> refs{
      {"lame_cylinder",
       "Eq. 13: the particle mean of |(sigma_r + sigma_theta) - S| / S against the exact Lame sum of the "
       "scene's solid annulus (benchmarks/coupled/cylinder_lame)",
       [](const RunFiles& r) { return lameError(r.dir, r.name, annulusFromScene(r.scene)).error; }},
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
