#pragma once
/// @brief A named, contiguous field over a box of indices with ncomp components (structure of arrays).
///
/// Storage is component-major: component c occupies one contiguous block of box.numPts() doubles,
/// x fastest inside it. The box is the stored (grown) region; `nghost` says how many of its layers
/// are ghosts around the valid region. Views give (i,j,k) access without virtual calls.
#include <cassert>
#include <string>
#include <vector>

#include "core/mesh/box.h"
#include "core/parallel/decomposition.h"

namespace mpmice::core {

/// Lightweight (i,j,k) view of one component; copy it into lambdas by value.
struct View {
  double* p = nullptr;
  IntVect lo{0, 0, 0};
  std::int64_t sy = 0, sz = 0;
  double& operator()(int i, int j, int k) const {
    return p[(i - lo[0]) + sy * (j - lo[1]) + sz * (k - lo[2])];
  }
};

struct ConstView {
  const double* p = nullptr;
  IntVect lo{0, 0, 0};
  std::int64_t sy = 0, sz = 0;
  const double& operator()(int i, int j, int k) const {
    return p[(i - lo[0]) + sy * (j - lo[1]) + sz * (k - lo[2])];
  }
};

class Field {
 public:
  Field() = default;
  Field(std::string name, Centering c, const Box& stored, int ncomp, int nghost, double init = 0.0);

  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] Centering centering() const { return centering_; }
  [[nodiscard]] const Box& box() const { return box_; }
  [[nodiscard]] int ncomp() const { return ncomp_; }
  [[nodiscard]] int nghost() const { return nghost_; }
  [[nodiscard]] std::int64_t npts() const { return npts_; }

  [[nodiscard]] double* data(int c = 0) { return data_.data() + c * npts_; }
  [[nodiscard]] const double* data(int c = 0) const { return data_.data() + c * npts_; }
  [[nodiscard]] View view(int c = 0);
  [[nodiscard]] ConstView view(int c = 0) const;
  double& operator()(int i, int j, int k, int c = 0) {
    assert(box_.contains(i, j, k));
    return data_[static_cast<std::size_t>(offset(i, j, k, c))];
  }
  double operator()(int i, int j, int k, int c = 0) const {
    assert(box_.contains(i, j, k));
    return data_[static_cast<std::size_t>(offset(i, j, k, c))];
  }
  /// Flat offset of (i, j, k), component c, in the storage: c npts + box().index(i, j, k), from
  /// strides kept at construction (Box::index recomputes the lengths with their validity tests).
  [[nodiscard]] std::int64_t offset(int i, int j, int k, int c = 0) const {
    return origin_ + c * npts_ + i + sy_ * j + sz_ * k;
  }
  void fill(double v) { data_.assign(data_.size(), v); }
  void fill(double v, int c);

  /// Copies region `src` of `from` into region `dst` of this field (same shape), all components.
  void copyRegion(const Field& from, const Box& src, const Box& dst);
  /// Packs region b (all components) into buf (appended); unpacks with add or copy.
  void pack(const Box& b, std::vector<double>& buf) const;
  std::size_t unpack(const Box& b, const double* buf, bool add);

 private:
  std::string name_;
  Centering centering_ = Centering::Cell;
  Box box_;
  int ncomp_ = 0, nghost_ = 0;
  std::int64_t npts_ = 0;
  std::int64_t sy_ = 0, sz_ = 0, origin_ = 0;  // offset = origin + c npts + i + sy j + sz k
  std::vector<double> data_;
};

}  // namespace mpmice::core
