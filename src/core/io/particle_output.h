#pragma once
/// @brief What a rank hands the OutputWriter about its particles: positions and named arrays.
///
/// A ParticleOutput does not own data: it holds spans over the solver's own structure-of-arrays
/// storage, each of length `count` (this rank's particle count, which may be zero). Positions are
/// given per direction; directions the mesh does not use may be left empty and are written as 0.
/// Scalars are one span each; vectors one span per component (any number of components, e.g. 2
/// in a 2D run, 9 for a deformation gradient). Every rank must list the same array names in the
/// same order (the datasets are created collectively); only the counts differ between ranks.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace mpmice::core {

struct ParticleOutput {
  struct Scalar {
    std::string name;
    std::span<const double> values;
  };
  struct Vector {
    std::string name;
    std::vector<std::span<const double>> components;
  };

  std::int64_t count = 0;
  std::array<std::span<const double>, 3> position;
  std::vector<Scalar> scalars;
  std::vector<Vector> vectors;

  ParticleOutput& addScalar(std::string name, std::span<const double> v) {
    scalars.push_back({std::move(name), v});
    return *this;
  }
  ParticleOutput& addVector(std::string name, std::vector<std::span<const double>> comps) {
    vectors.push_back({std::move(name), std::move(comps)});
    return *this;
  }
};

}  // namespace mpmice::core
