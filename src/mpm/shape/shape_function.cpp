#include "mpm/shape/shape_function.h"

namespace mpmice::mpm {

namespace {
struct Entry {
  const char* name;
  ShapeKind kind;
  int width;
};
// The one registry of shape functions: scene name, kind, stencil width.
constexpr Entry kShapes[] = {
    {LinearShape::kName, ShapeKind::Linear, LinearShape::kNodes},
    {GimpShape::kName, ShapeKind::Gimp, GimpShape::kNodes},
    {BSpline2Shape::kName, ShapeKind::BSpline2, BSpline2Shape::kNodes},
    {BSpline3Shape::kName, ShapeKind::BSpline3, BSpline3Shape::kNodes},
};
}  // namespace

const std::vector<std::string>& shapeFunctionNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& e : kShapes) n.emplace_back(e.name);
    return n;
  }();
  return names;
}

ShapeKind parseShapeFunction(const std::string& name) {
  for (const auto& e : kShapes)
    if (name == e.name) return e.kind;
  std::string valid;
  for (const auto& e : kShapes) valid += std::string(valid.empty() ? "" : ", ") + e.name;
  throw std::invalid_argument("mpm.shape_function: unknown shape function '" + name +
                              "'; valid choices: " + valid);
}

const char* toString(ShapeKind k) {
  for (const auto& e : kShapes)
    if (e.kind == k) return e.name;
  return "?";
}

int stencilWidth(ShapeKind k) {
  for (const auto& e : kShapes)
    if (e.kind == k) return e.width;
  return 0;
}

}  // namespace mpmice::mpm
