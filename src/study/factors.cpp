#include "study/factors.h"

#include <set>
#include <stdexcept>

namespace mpmice::study {

namespace {

/// The point with a level's settings put in place (keys keep the point's order). Built anew:
/// assigning to a YAML::Node would rewrite the node it refers to, which `base` shares.
Settings withLevel(const Settings& point, const Settings& level, const std::string& factor) {
  for (const auto& [k, v] : level) {
    bool found = false;
    for (const auto& kv : point) found = found || kv.first == k;
    if (!found)
      throw std::invalid_argument("factor '" + factor + "': key '" + k +
                                  "' is not in `base` (every varied key needs its base value)");
  }
  Settings out;
  for (const auto& [bk, bv] : point) {
    const YAML::Node* value = &bv;
    for (const auto& [k, v] : level)
      if (k == bk) value = &v;
    out.emplace_back(bk, *value);
  }
  return out;
}

std::string pointText(const Settings& s) {
  std::string t;
  for (const auto& [k, v] : s) t += k + "=" + valueText(v) + "\n";
  return t;
}

}  // namespace

std::vector<Point> expandFactors(const Settings& base, const std::vector<Factor>& factors,
                                 const std::vector<Slice>& slices) {
  std::vector<Point> points;
  std::set<std::string> seen;
  auto add = [&](Settings s) {
    if (seen.insert(pointText(s)).second) points.push_back(Point{std::move(s)});
  };
  add(base);
  for (const auto& f : factors) {
    if (f.levels.empty()) throw std::invalid_argument("factor '" + f.name + "' has no levels");
    for (const auto& level : f.levels) add(withLevel(base, level, f.name));
  }
  for (const auto& slice : slices) {
    std::size_t total = 1;
    for (const auto& f : slice.factors) {
      if (f.levels.empty()) throw std::invalid_argument("slice factor '" + f.name + "' has no levels");
      total *= f.levels.size();
    }
    for (std::size_t p = 0; p < total; ++p) {
      Settings s = base;
      std::size_t rest = p;
      std::vector<std::size_t> pick(slice.factors.size());
      for (std::size_t k = slice.factors.size(); k-- > 0;) {  // the last factor fastest
        pick[k] = rest % slice.factors[k].levels.size();
        rest /= slice.factors[k].levels.size();
      }
      for (std::size_t k = 0; k < slice.factors.size(); ++k)
        s = withLevel(s, slice.factors[k].levels[pick[k]], slice.factors[k].name);
      add(std::move(s));
    }
  }
  return points;
}

}  // namespace mpmice::study
