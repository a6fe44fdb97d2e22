#pragma once
/// @brief One factor at a time around a base point, and slices through it: the compact form of a
/// study file (docs/tradeoffs.md, "One factor at a time").
///
///     base:                                  # the centre: every swept key with its value there
///       time.cfl: 0.4
///       coupling.schedule: monolithic
///       coupling.acceleration.type: none
///     factors:                               # each factor's levels, varied one at a time
///       time.cfl: [0.1, 0.7]                 # a key path: each level one value of that key
///       schedule:                            # a name: each level moves several keys together
///         - {coupling.schedule: implicit_serial, coupling.acceleration.type: iqn_ils}
///     slices:                                # full grids over two or more factors
///       - {time.cfl: all, schedule: all}     # `all`: the factor's levels; or a list of levels
///
/// The points are the base, then each factor's levels in the file's order, then each slice's grid
/// (the first factor slowest); every point gives every key of `base` (so the CSV's columns are
/// complete), and a point equal to an earlier one is not run again.
#include <string>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "study/grid.h"

namespace mpmice::study {

using Settings = std::vector<std::pair<std::string, YAML::Node>>;

/// A factor: its name (a key path, or a label) and its levels, each the settings it changes.
struct Factor {
  std::string name;
  std::vector<Settings> levels;
};

/// A slice: factors and, for each, the levels it takes (in the slice's order).
struct Slice {
  std::vector<Factor> factors;
};

/// The base, each factor's levels one at a time, then each slice's grid; equal points once.
/// A level's key that `base` lacks is std::invalid_argument naming the factor and the key.
std::vector<Point> expandFactors(const Settings& base, const std::vector<Factor>& factors,
                                 const std::vector<Slice>& slices);

}  // namespace mpmice::study
