// The accelerations' restart state: what they carry from one step to the next, stored exactly so
// that a resumed implicit run iterates as the uninterrupted one does (IQN-ILS: the reused columns
// V and W with their norms and ages, the QR of V as it was updated, not rebuilt, the
// preconditioner's weights; Aitken: the last relaxation).
#include <stdexcept>

#include "coupler/acceleration/iqn_ils.h"
#include "coupler/acceleration/relaxation.h"

namespace mpmice::coupler {

namespace {
void putVector(core::CheckpointData& d, const std::string& name, const Eigen::VectorXd& v) {
  d.put(name, std::vector<double>(v.data(), v.data() + v.size()));
}
Eigen::VectorXd getVector(const core::CheckpointData& d, const std::string& name) {
  const auto& v = d.get(name);
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}
std::string key(const std::string& prefix, const char* what, std::size_t j) {
  std::string s = prefix;
  s += what;
  s += std::to_string(j);
  return s;
}
}  // namespace

void AitkenRelaxation::save(core::CheckpointData& data, const std::string& prefix) const {
  data.put(prefix + ".aitken", std::vector<double>{w_, first_ ? 1.0 : 0.0});
  putVector(data, prefix + ".aitken_r", rPrev_);
}

void AitkenRelaxation::load(const core::CheckpointData& data, const std::string& prefix) {
  const auto& a = data.get(prefix + ".aitken");
  if (a.size() != 2) throw std::invalid_argument(data.source() + ": checkpoint entry '" + prefix + ".aitken' is malformed");
  w_ = a[0];
  first_ = a[1] != 0.0;
  rPrev_ = getVector(data, prefix + ".aitken_r");
}

void IqnIls::save(core::CheckpointData& data, const std::string& prefix) const {
  std::vector<double> meta{static_cast<double>(cols_.size()), havePrev_ ? 1.0 : 0.0, static_cast<double>(used_),
                           static_cast<double>(rebuilds_), static_cast<double>(qr_.cols())};
  data.put(prefix + ".iqn", std::move(meta));
  std::vector<double> colMeta, seg;
  for (std::size_t j = 0; j < cols_.size(); ++j) {
    putVector(data, key(prefix, ".iqn_v", j), cols_[j].v);
    putVector(data, key(prefix, ".iqn_w", j), cols_[j].w);
    colMeta.push_back(cols_[j].norm);
    colMeta.push_back(static_cast<double>(cols_[j].age));
  }
  data.put(prefix + ".iqn_columns", std::move(colMeta));
  for (std::size_t j = 0; j < qr_.q().size(); ++j) putVector(data, key(prefix, ".iqn_q", j), qr_.q()[j]);
  const Eigen::MatrixXd& r = qr_.r();
  data.put(prefix + ".iqn_r", std::vector<double>(r.data(), r.data() + r.size()));
  data.put(prefix + ".iqn_rdims", std::vector<double>{static_cast<double>(r.rows()), static_cast<double>(r.cols())});
  putVector(data, prefix + ".iqn_rprev", rPrev_);
  putVector(data, prefix + ".iqn_xtprev", xtPrev_);
  for (const Segment& s : segments_) {
    seg.push_back(static_cast<double>(s.offset));
    seg.push_back(static_cast<double>(s.size));
    seg.push_back(static_cast<double>(s.group));
  }
  data.put(prefix + ".iqn_segments", std::move(seg));
  data.put(prefix + ".iqn_group_weights", groupWeight_);
  data.put(prefix + ".iqn_residual_share", residualShare_);
  putVector(data, prefix + ".iqn_weight", weight_);
}

void IqnIls::load(const core::CheckpointData& data, const std::string& prefix) {
  const auto& meta = data.get(prefix + ".iqn");
  if (meta.size() != 5) throw std::invalid_argument(data.source() + ": checkpoint entry '" + prefix + ".iqn' is malformed");
  const auto ncols = static_cast<std::size_t>(meta[0]);
  havePrev_ = meta[1] != 0.0;
  used_ = static_cast<int>(meta[2]);
  rebuilds_ = static_cast<int>(meta[3]);
  const auto nq = static_cast<std::size_t>(meta[4]);
  const auto& colMeta = data.get(prefix + ".iqn_columns");
  if (colMeta.size() != 2 * ncols)
    throw std::invalid_argument(data.source() + ": checkpoint entry '" + prefix + ".iqn_columns' is malformed");
  cols_.clear();
  for (std::size_t j = 0; j < ncols; ++j) {
    Column c;
    c.v = getVector(data, key(prefix, ".iqn_v", j));
    c.w = getVector(data, key(prefix, ".iqn_w", j));
    c.norm = colMeta[2 * j];
    c.age = static_cast<int>(colMeta[2 * j + 1]);
    cols_.push_back(std::move(c));
  }
  std::vector<Eigen::VectorXd> q;
  for (std::size_t j = 0; j < nq; ++j) q.push_back(getVector(data, key(prefix, ".iqn_q", j)));
  const auto& rv = data.get(prefix + ".iqn_r");
  const auto& rd = data.get(prefix + ".iqn_rdims");
  if (rd.size() != 2 || rv.size() != static_cast<std::size_t>(rd[0] * rd[1]))
    throw std::invalid_argument(data.source() + ": checkpoint entry '" + prefix + ".iqn_r' is malformed");
  Eigen::MatrixXd r = Eigen::Map<const Eigen::MatrixXd>(rv.data(), static_cast<Eigen::Index>(rd[0]),
                                                         static_cast<Eigen::Index>(rd[1]));
  qr_.restore(std::move(q), std::move(r));
  rPrev_ = getVector(data, prefix + ".iqn_rprev");
  xtPrev_ = getVector(data, prefix + ".iqn_xtprev");
  const auto& seg = data.get(prefix + ".iqn_segments");
  segments_.clear();
  for (std::size_t k = 0; k + 2 < seg.size(); k += 3)
    segments_.push_back({static_cast<Eigen::Index>(seg[k]), static_cast<Eigen::Index>(seg[k + 1]), static_cast<int>(seg[k + 2])});
  groupWeight_ = data.get(prefix + ".iqn_group_weights");
  residualShare_ = data.get(prefix + ".iqn_residual_share");
  weight_ = getVector(data, prefix + ".iqn_weight");
}

}  // namespace mpmice::coupler
