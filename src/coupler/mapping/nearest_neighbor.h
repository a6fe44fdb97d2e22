#pragma once
/// @brief Nearest-neighbour interface mapping.
///
/// Consistent: each target point takes the value of its nearest source point. Conservative: each
/// target's quantity goes whole to that same source point (keeps the total, not the moment).
/// Distances use the first dim coordinates; equally near sources go to the lower source index.
/// compute() builds a k-d tree over the sources (median splits on the widest axis, small leaves):
/// O(nS log nS) to build, about O(log nS) per target.
#include <cstddef>
#include <vector>

#include "coupler/mapping/mapping.h"

namespace mpmice::coupler {

class NearestNeighbor final : public Mapping {
 public:
  void compute(const PointCloud& source, const PointCloud& target, int dim) override;
  [[nodiscard]] const char* name() const override { return "nearest_neighbor"; }
  /// The nearest source point of each target point (M as indices).
  [[nodiscard]] const std::vector<std::size_t>& nearest() const { return nearest_; }

 private:
  void applyConsistent(const double* in, double* out, int ncomp) const override;
  void applyConservative(const double* in, double* out, int ncomp) const override;

  std::vector<std::size_t> nearest_;
};

}  // namespace mpmice::coupler
