#pragma once
/// @brief Geometry helpers for scene shapes beyond ShapeSpec::contains: the names of the shape
/// types and axis-aligned bounds (used to check that solids lie inside the mesh).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/scene/scene.h"

namespace mpmice::core::scene_detail {

/// Shape types a scene may name ("circle" is read as "sphere" in 2D).
const std::vector<std::string>& shapeTypes();

/// Bounds [lo, hi] of the shape in the first `dim` directions, when they can be computed: box,
/// sphere, annulus, cylinder (finite in 3D), union (all children computable), difference (the
/// first child's bounds).
std::optional<std::pair<RealVect, RealVect>> shapeBounds(const ShapeSpec& s, int dim);

}  // namespace mpmice::core::scene_detail
