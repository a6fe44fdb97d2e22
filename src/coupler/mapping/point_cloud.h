#pragma once
/// @brief A cloud of points in structure-of-arrays form: one side of an interface mapping.
///
/// x[d][i] is coordinate d of point i. A cloud always stores three coordinates; a mapping of
/// dimension 2 ignores x[2] (a 2D OpenFOAM patch has face centres at z = 0.5 and points at
/// z = 0 and 1, all of which are treated alike).
#include <array>
#include <cstddef>
#include <vector>

namespace mpmice::coupler {

struct PointCloud {
  std::array<std::vector<double>, 3> x;

  [[nodiscard]] std::size_t size() const { return x[0].size(); }
  void add(double px, double py, double pz) {
    x[0].push_back(px);
    x[1].push_back(py);
    x[2].push_back(pz);
  }
};

}  // namespace mpmice::coupler
