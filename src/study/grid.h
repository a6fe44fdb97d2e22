#pragma once
/// @brief The points of a study: the full grid over its axes (the first axis varies slowest), or
/// an explicit list. A point is one value per key path.
#include <string>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace mpmice::study {

/// One axis: a key path (or `ranks`) and its values, in order.
struct Axis {
  std::string key;
  std::vector<YAML::Node> values;
};

/// One grid point: (key, value) in the axes' order.
struct Point {
  std::vector<std::pair<std::string, YAML::Node>> settings;
};

/// Every combination of the axes' values, the first axis varying slowest, the last fastest.
/// No axes give one point (the base scene); an axis without values is std::invalid_argument.
std::vector<Point> expandGrid(const std::vector<Axis>& axes);

/// A value as one line of text: a scalar as written, a mapping or list in flow style
/// (`{type: aitken, relaxation: 0.5}`).
std::string valueText(const YAML::Node& v);

/// The point as a short label, its values joined by " / " (the plot's label).
std::string pointLabel(const Point& p);

/// The point's run folder name: `NNN_` and its values with every character outside
/// [A-Za-z0-9.+-] replaced by '_' (`003_0.05_bspline2_4_monolithic`).
std::string pointFolder(const Point& p, std::size_t index);

}  // namespace mpmice::study
