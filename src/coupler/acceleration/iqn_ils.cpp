#include "coupler/acceleration/iqn_ils.h"

#include <algorithm>
#include <cmath>

namespace mpmice::coupler {

Eigen::VectorXd IqnIls::scaled(const Eigen::VectorXd& v) const {
  return weight_.size() == v.size() ? Eigen::VectorXd(v.cwiseProduct(weight_)) : v;
}

void IqnIls::insert(Column c) {
  const Eigen::VectorXd pv = scaled(c.v);
  c.norm = std::sqrt(comm_.sum(pv.squaredNorm()));
  qr_.pushFront(pv);
  cols_.push_front(std::move(c));
}

void IqnIls::filter() {
  for (int j = 0; j < qr_.cols();) {
    const double norm = cols_[static_cast<std::size_t>(j)].norm;
    if (!(norm > 0) || qr_.diagonal(j) < filter_ * norm) {
      qr_.erase(j);
      cols_.erase(cols_.begin() + j);
    } else {
      ++j;
    }
  }
}

void IqnIls::setSegments(const std::vector<Segment>& segments) {
  if (!precondition_) return;
  const bool same = segments.size() == segments_.size() &&
                    std::equal(segments.begin(), segments.end(), segments_.begin(), [](const Segment& a, const Segment& b) {
                      return a.offset == b.offset && a.size == b.size && a.group == b.group;
                    });
  if (same) return;
  segments_ = segments;
  int groups = 0;
  for (const auto& s : segments_) groups = std::max(groups, s.group + 1);
  groups = comm_.max(groups);  // a rank may hold no element of some group
  groupWeight_.assign(static_cast<std::size_t>(groups), 1.0);
  residualShare_.assign(static_cast<std::size_t>(groups), 0.0);
  weight_.resize(0);
  cols_.clear();
  qr_.clear();
}

void IqnIls::accumulateResidual(const Eigen::VectorXd& r) {
  if (segments_.empty()) return;
  std::vector<double> sq(groupWeight_.size(), 0.0);
  for (const auto& s : segments_)
    if (s.offset + s.size <= r.size()) sq[static_cast<std::size_t>(s.group)] += r.segment(s.offset, s.size).squaredNorm();
  comm_.sumInPlace(sq);
  double total = 0;
  for (double& v : sq) total += (v = std::sqrt(v));
  if (total > 0)
    for (std::size_t g = 0; g < sq.size(); ++g) residualShare_[g] += sq[g] / total;
}

std::vector<double> IqnIls::proposedWeights() const {
  std::vector<double> w(residualShare_.size(), 1.0);
  for (std::size_t g = 0; g < w.size(); ++g)
    if (residualShare_[g] > 0) w[g] = 1.0 / residualShare_[g];
  return w;
}

void IqnIls::adopt(const std::vector<double>& w) {
  groupWeight_ = w;
  Eigen::Index n = 0;
  for (const auto& s : segments_) n = std::max(n, s.offset + s.size);
  weight_ = Eigen::VectorXd::Ones(n);
  for (const auto& s : segments_) weight_.segment(s.offset, s.size).setConstant(w[static_cast<std::size_t>(s.group)]);
  // The columns were factorised with the old weights: factorise them again, oldest first.
  if (cols_.empty()) return;
  std::deque<Column> old;
  old.swap(cols_);
  qr_.clear();
  for (auto it = old.rbegin(); it != old.rend(); ++it) {
    insert(std::move(*it));
    filter();
  }
  ++rebuilds_;
}

Eigen::VectorXd IqnIls::performAcceleration(const Eigen::VectorXd& x, const Eigen::VectorXd& xt) {
  const Eigen::VectorXd r = xt - x;
  accumulateResidual(r);
  if (!segments_.empty() && cols_.empty() && !havePrev_) adopt(proposedWeights());  // free: no columns yet
  if (havePrev_) {
    insert({r - rPrev_, xt - xtPrev_, 0.0, 0});
    filter();
  }
  rPrev_ = r;
  xtPrev_ = xt;
  havePrev_ = true;
  used_ = qr_.cols();
  if (used_ == 0) return x + w0_ * r;
  const Eigen::VectorXd a = qr_.solve(-scaled(r));
  Eigen::VectorXd next = xt;
  for (int j = 0; j < used_; ++j) next += a[j] * cols_[static_cast<std::size_t>(j)].w;
  return next;
}

void IqnIls::iterationsConverged() {
  for (auto& c : cols_) ++c.age;
  while (!cols_.empty() && cols_.back().age > reuse_) {
    qr_.erase(qr_.cols() - 1);
    cols_.pop_back();
  }
  havePrev_ = false;
  if (!segments_.empty()) {
    const std::vector<double> w = proposedWeights();
    bool moved = false;
    for (std::size_t g = 0; g < w.size(); ++g) {
      const double ratio = w[g] / groupWeight_[g];
      moved = moved || ratio > 10.0 || ratio < 0.1;
    }
    if (moved) adopt(w);
    std::fill(residualShare_.begin(), residualShare_.end(), 0.0);
  }
}

}  // namespace mpmice::coupler
