#include "core/scene/shape.h"

#include <algorithm>
#include <cmath>

namespace mpmice::core {

namespace {

/// Squared distance from the axis and the coordinate along the axis of x, for round shapes.
/// dim < 3: circles in the x-y plane (intervals in 1D), so the axial coordinate is 0.
void axisCoordinates(const ShapeSpec& s, const RealVect& x, int dim, double& radial2, double& axial) {
  RealVect r{0, 0, 0};
  for (int d = 0; d < dim; ++d) r[d] = x[d] - s.center[d];
  const double all2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
  if (dim < 3) {
    radial2 = all2;
    axial = 0;
    return;
  }
  const double n = std::sqrt(s.axis[0] * s.axis[0] + s.axis[1] * s.axis[1] + s.axis[2] * s.axis[2]);
  axial = (r[0] * s.axis[0] + r[1] * s.axis[1] + r[2] * s.axis[2]) / n;
  radial2 = std::max(0.0, all2 - axial * axial);
}

bool withinLength(const ShapeSpec& s, double axial) { return s.length <= 0 || std::abs(axial) <= 0.5 * s.length; }

}  // namespace

bool ShapeSpec::contains(const RealVect& x, int dim) const {
  if (type == "box") {
    for (int d = 0; d < dim; ++d)
      if (x[d] < lo[d] || x[d] > hi[d]) return false;
    return true;
  }
  if (type == "sphere" || type == "circle") {
    double r2 = 0;
    for (int d = 0; d < dim; ++d) r2 += (x[d] - center[d]) * (x[d] - center[d]);
    return r2 <= radius * radius;
  }
  if (type == "cylinder" || type == "annulus") {
    double radial2 = 0, axial = 0;
    axisCoordinates(*this, x, dim, radial2, axial);
    if (!withinLength(*this, axial)) return false;
    if (type == "cylinder") return radial2 <= radius * radius;
    return radial2 >= inner_radius * inner_radius && radial2 <= outer_radius * outer_radius;
  }
  if (type == "union")
    return std::any_of(children.begin(), children.end(), [&](const ShapeSpec& c) { return c.contains(x, dim); });
  if (type == "difference") {
    if (children.empty() || !children.front().contains(x, dim)) return false;
    return std::none_of(children.begin() + 1, children.end(),
                        [&](const ShapeSpec& c) { return c.contains(x, dim); });
  }
  return false;
}

namespace scene_detail {

const std::vector<std::string>& shapeTypes() {
  static const std::vector<std::string> t{"box", "sphere", "circle", "cylinder", "annulus", "union", "difference"};
  return t;
}

std::optional<std::pair<RealVect, RealVect>> shapeBounds(const ShapeSpec& s, int dim) {
  RealVect lo{0, 0, 0}, hi{0, 0, 0};
  if (s.type == "box") return std::make_pair(s.lo, s.hi);
  if (s.type == "sphere" || s.type == "circle" || ((s.type == "cylinder" || s.type == "annulus") && dim < 3)) {
    const double r = s.type == "annulus" ? s.outer_radius : s.radius;
    for (int d = 0; d < dim; ++d) {
      lo[d] = s.center[d] - r;
      hi[d] = s.center[d] + r;
    }
    return std::make_pair(lo, hi);
  }
  if (s.type == "cylinder" || s.type == "annulus") {  // 3D
    if (s.length <= 0) return std::nullopt;
    const double r = s.type == "annulus" ? s.outer_radius : s.radius;
    const double n = std::sqrt(s.axis[0] * s.axis[0] + s.axis[1] * s.axis[1] + s.axis[2] * s.axis[2]);
    for (int d = 0; d < 3; ++d) {
      const double a = s.axis[d] / n;
      const double half = 0.5 * s.length * std::abs(a) + r * std::sqrt(std::max(0.0, 1.0 - a * a));
      lo[d] = s.center[d] - half;
      hi[d] = s.center[d] + half;
    }
    return std::make_pair(lo, hi);
  }
  if (s.type == "difference" && !s.children.empty()) return shapeBounds(s.children.front(), dim);
  if (s.type == "union" && !s.children.empty()) {
    auto b = shapeBounds(s.children.front(), dim);
    for (std::size_t i = 1; b && i < s.children.size(); ++i) {
      const auto c = shapeBounds(s.children[i], dim);
      if (!c) return std::nullopt;
      for (int d = 0; d < dim; ++d) {
        b->first[d] = std::min(b->first[d], c->first[d]);
        b->second[d] = std::max(b->second[d], c->second[d]);
      }
    }
    return b;
  }
  return std::nullopt;
}

}  // namespace scene_detail
}  // namespace mpmice::core
