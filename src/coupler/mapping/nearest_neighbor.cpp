#include "coupler/mapping/nearest_neighbor.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace mpmice::coupler {

namespace {

/// A k-d tree over the first dim coordinates of a cloud; nodes split at the median of the widest
/// axis of their points, leaves hold at most kLeaf points.
class KdTree {
 public:
  KdTree(const PointCloud& cloud, int dim) : cloud_(cloud), dim_(dim), perm_(cloud.size()) {
    std::iota(perm_.begin(), perm_.end(), std::size_t{0});
    nodes_.reserve(2 * (cloud.size() / kLeaf + 1));
    build(0, perm_.size());
  }

  /// Index of the point nearest to q (dim coordinates); the lower index among equally near ones.
  [[nodiscard]] std::size_t nearest(const double* q) const {
    Best best;
    search(0, q, best);
    return best.index;
  }

 private:
  static constexpr std::size_t kLeaf = 8;
  struct Node {
    std::size_t begin = 0, end = 0;  // range in perm_
    std::size_t left = 0, right = 0;
    double split = 0.0;
    int axis = -1;  // -1: leaf
  };
  struct Best {
    double d2 = std::numeric_limits<double>::infinity();
    std::size_t index = std::numeric_limits<std::size_t>::max();
  };

  [[nodiscard]] double coord(int d, std::size_t i) const {
    return cloud_.x[static_cast<std::size_t>(d)][i];
  }

  std::size_t build(std::size_t begin, std::size_t end) {
    const std::size_t id = nodes_.size();
    nodes_.push_back(Node{begin, end});
    if (end - begin <= kLeaf) return id;
    int axis = -1;
    double widest = 0.0;
    for (int d = 0; d < dim_; ++d) {
      double lo = coord(d, perm_[begin]), hi = lo;
      for (std::size_t k = begin + 1; k < end; ++k) {
        lo = std::min(lo, coord(d, perm_[k]));
        hi = std::max(hi, coord(d, perm_[k]));
      }
      if (hi - lo > widest) {
        widest = hi - lo;
        axis = d;
      }
    }
    if (axis < 0) return id;  // all points coincide: one leaf
    const std::size_t mid = begin + (end - begin) / 2;
    const auto& xa = cloud_.x[static_cast<std::size_t>(axis)];
    const auto first = perm_.begin();
    std::nth_element(first + static_cast<std::ptrdiff_t>(begin), first + static_cast<std::ptrdiff_t>(mid),
                     first + static_cast<std::ptrdiff_t>(end), [&xa](std::size_t a, std::size_t b) {
                       return xa[a] < xa[b] || (xa[a] == xa[b] && a < b);  // deterministic
                     });
    const double split = xa[perm_[mid]];
    const std::size_t left = build(begin, mid);  // left: coordinates <= split
    const std::size_t right = build(mid, end);   // right: coordinates >= split
    Node& n = nodes_[id];
    n.axis = axis;
    n.split = split;
    n.left = left;
    n.right = right;
    return id;
  }

  void search(std::size_t id, const double* q, Best& best) const {
    const Node& n = nodes_[id];
    if (n.axis < 0) {
      for (std::size_t k = n.begin; k < n.end; ++k) {
        const std::size_t i = perm_[k];
        double d2 = 0.0;
        for (int d = 0; d < dim_; ++d) {
          const double dx = q[d] - coord(d, i);
          d2 += dx * dx;
        }
        if (d2 < best.d2 || (d2 == best.d2 && i < best.index)) best = Best{d2, i};
      }
      return;
    }
    const double diff = q[n.axis] - n.split;
    search(diff < 0.0 ? n.left : n.right, q, best);
    // The far side is at least |diff| away; <= so that equally near points with a lower index
    // are still found.
    if (diff * diff <= best.d2) search(diff < 0.0 ? n.right : n.left, q, best);
  }

  const PointCloud& cloud_;
  int dim_;
  std::vector<std::size_t> perm_;
  std::vector<Node> nodes_;
};

}  // namespace

void NearestNeighbor::compute(const PointCloud& source, const PointCloud& target, int dim) {
  beginCompute(source, target, dim);
  const KdTree tree(source, dim);
  nearest_.assign(target.size(), 0);
  for (std::size_t t = 0; t < target.size(); ++t) {
    double q[3] = {0.0, 0.0, 0.0};
    for (int d = 0; d < dim; ++d) q[d] = target.x[static_cast<std::size_t>(d)][t];
    nearest_[t] = tree.nearest(q);
  }
  endCompute();
}

void NearestNeighbor::applyConsistent(const double* in, double* out, int ncomp) const {
  const auto nc = static_cast<std::size_t>(ncomp);
  for (std::size_t t = 0; t < nearest_.size(); ++t)
    for (std::size_t c = 0; c < nc; ++c) out[t * nc + c] = in[nearest_[t] * nc + c];
}

void NearestNeighbor::applyConservative(const double* in, double* out, int ncomp) const {
  const auto nc = static_cast<std::size_t>(ncomp);
  std::fill(out, out + sourceSize() * nc, 0.0);
  for (std::size_t t = 0; t < nearest_.size(); ++t)
    for (std::size_t c = 0; c < nc; ++c) out[nearest_[t] * nc + c] += in[t * nc + c];
}

}  // namespace mpmice::coupler
