#pragma once
// The observed order of convergence of a study: the least-squares slope of ln e against ln h.
#include <cmath>
#include <vector>

namespace mpmice::test {

inline double observedOrder(const std::vector<double>& h, const std::vector<double>& e) {
  const double n = static_cast<double>(h.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < h.size(); ++k) {
    const double x = std::log(h[k]), y = std::log(e[k]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace mpmice::test
