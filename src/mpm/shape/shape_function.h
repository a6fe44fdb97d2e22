#pragma once
/// @brief The shape-function family, chosen by its scene name (`mpm.shape_function`) through one
/// registry, and the compile-time dispatch the hot loops use.
///
/// Hot loops are templates over the shape type (LinearShape, GimpShape, BSpline2Shape,
/// BSpline3Shape) and the dimension; withShape() turns the run-time choice into one call of the
/// matching instantiation, so there is no per-particle virtual call. An unknown name is an error
/// that lists the valid ones.
#include <stdexcept>
#include <string>
#include <vector>

#include "mpm/shape/bspline2.h"
#include "mpm/shape/bspline3.h"
#include "mpm/shape/gimp.h"
#include "mpm/shape/linear.h"

namespace mpmice::mpm {

enum class ShapeKind { Linear, Gimp, BSpline2, BSpline3 };

/// The valid scene names, in registry order.
const std::vector<std::string>& shapeFunctionNames();
/// Name -> kind; throws std::invalid_argument listing the valid names.
ShapeKind parseShapeFunction(const std::string& name);
const char* toString(ShapeKind k);
/// Nodes per direction of the stencil.
int stencilWidth(ShapeKind k);

/// Calls f(Shape{}) with the shape type matching k.
template <class F>
decltype(auto) withShape(ShapeKind k, F&& f) {
  switch (k) {
    case ShapeKind::Linear: return f(LinearShape{});
    case ShapeKind::Gimp: return f(GimpShape{});
    case ShapeKind::BSpline2: return f(BSpline2Shape{});
    case ShapeKind::BSpline3: return f(BSpline3Shape{});
  }
  throw std::logic_error("withShape: bad ShapeKind");
}

}  // namespace mpmice::mpm
