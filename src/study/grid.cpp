#include "study/grid.h"

#include <cctype>
#include <cstdio>
#include <stdexcept>

namespace mpmice::study {

std::vector<Point> expandGrid(const std::vector<Axis>& axes) {
  std::size_t total = 1;
  for (const auto& a : axes) {
    if (a.values.empty()) throw std::invalid_argument("axis '" + a.key + "' has no values");
    total *= a.values.size();
  }
  std::vector<Point> points(total);
  for (std::size_t p = 0; p < total; ++p) {
    std::size_t rest = p;
    std::vector<std::pair<std::string, YAML::Node>> s(axes.size());
    for (std::size_t k = axes.size(); k-- > 0;) {  // the last axis fastest
      const auto& a = axes[k];
      s[k] = {a.key, a.values[rest % a.values.size()]};
      rest /= a.values.size();
    }
    points[p].settings = std::move(s);
  }
  return points;
}

std::string valueText(const YAML::Node& v) {
  if (v.IsScalar()) return v.Scalar();
  YAML::Emitter e;
  e << YAML::Flow << v;
  return e.c_str();
}

std::string pointLabel(const Point& p) {
  std::string s;
  for (const auto& [k, v] : p.settings) s += (s.empty() ? "" : " / ") + valueText(v);
  return s.empty() ? "base" : s;
}

std::string pointFolder(const Point& p, std::size_t index) {
  char head[16];
  std::snprintf(head, sizeof head, "%03zu", index);
  std::string s = head;
  for (const auto& [k, v] : p.settings) {
    s.push_back('_');
    for (char c : valueText(v))
      s.push_back(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '+' || c == '-' ? c : '_');
  }
  return s;
}

}  // namespace mpmice::study
