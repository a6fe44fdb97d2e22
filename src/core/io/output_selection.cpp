#include "core/io/output_selection.h"

#include <algorithm>
#include <stdexcept>

namespace mpmice::core {

bool outputSelected(const std::vector<std::string>& wanted, const std::string& name,
                    const std::vector<std::string>& prefixes) {
  if (wanted.empty()) return true;
  for (const auto& w : wanted) {
    if (w == name) return true;
    for (const auto& p : prefixes)
      if (name == p + "_" + w) return true;
  }
  return false;
}

std::vector<Field> selectFields(std::vector<Field> all, const std::vector<std::string>& wanted,
                                const std::vector<std::string>& prefixes) {
  std::vector<Field> out;
  for (auto& f : all)
    if (outputSelected(wanted, f.name(), prefixes)) out.push_back(std::move(f));
  return out;
}

ParticleOutput selectParticles(ParticleOutput all, const std::vector<std::string>& wanted) {
  std::erase_if(all.scalars, [&](const ParticleOutput::Scalar& s) { return !outputSelected(wanted, s.name); });
  std::erase_if(all.vectors, [&](const ParticleOutput::Vector& v) { return !outputSelected(wanted, v.name); });
  return all;
}

void checkOutputFields(const std::vector<std::string>& wanted, const std::vector<std::string>& offered,
                       const std::vector<std::string>& prefixes, const std::string& program) {
  for (const auto& w : wanted) {
    const bool any = std::any_of(offered.begin(), offered.end(),
                                 [&](const std::string& n) { return outputSelected({w}, n, prefixes); });
    if (any) continue;
    std::string list;
    for (const auto& n : offered) list += (list.empty() ? "" : ", ") + n;
    throw std::invalid_argument("output.fields: " + program + " offers no field '" + w + "'; valid names: " + list +
                                " (a per-material name without its material selects it for every material; "
                                "or leave the list empty for all)");
  }
}

}  // namespace mpmice::core
