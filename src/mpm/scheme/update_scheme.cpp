#include "mpm/scheme/update_scheme.h"

#include <stdexcept>

namespace mpmice::mpm {

const std::vector<SchemeTraits>& updateSchemes() {
  static const std::vector<SchemeTraits> s = {
      {"usf", UpdateScheme::USF, true, false, "update stress first"},
      {"usl", UpdateScheme::USL, false, false, "update stress last"},
      {"musl", UpdateScheme::MUSL, false, true, "modified update stress last (velocity remap)"},
  };
  return s;
}

const SchemeTraits& parseUpdateScheme(const std::string& name) {
  for (const auto& t : updateSchemes())
    if (name == t.name) return t;
  std::string valid;
  for (const auto& t : updateSchemes()) valid += std::string(valid.empty() ? "" : ", ") + t.name;
  throw std::invalid_argument("mpm.update: unknown update scheme '" + name +
                              "'; valid choices: " + valid);
}

}  // namespace mpmice::mpm
