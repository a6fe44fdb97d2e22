#pragma once
/// @brief IQN-ILS: interface quasi-Newton with an inverse Jacobian from least squares.
///
/// Columns V (differences of residuals r = x~ - x) and W (differences of outputs x~) are kept
/// over the iterations of the current step and of up to `reuse` past steps, newest first. The
/// next input is
///   x^{k+1} = x~^k + W a,   a = argmin || P (V a + r^k) ||,
/// with the QR factorisation of P V updated column by column (QrFactorization: a new column
/// inserted at the front, expired and filtered ones deleted; never rebuilt per iteration). The
/// QR filter drops a column whose part orthogonal to the newer ones is below `filter` times its
/// norm (near-linear dependence). P is the residual-sum preconditioner (as preCICE's): with the
/// iterate split into named segments (setSegments), each segment is weighted by the inverse of
/// its accumulated share of the residual norm, so fields in kg, m/s, K and Pa weigh alike; the
/// weights are set while no column exists and renewed at the end of a step only when one moved
/// by more than a factor 10 (the QR is then rebuilt once). Without columns (the first
/// iteration) it relaxes with the initial relaxation.
#include <deque>
#include <vector>

#include "coupler/acceleration/acceleration.h"
#include "coupler/acceleration/qr_factorization.h"

namespace mpmice::coupler {

class IqnIls final : public Acceleration {
 public:
  IqnIls(double initialRelaxation, int reuse, double filter, core::Comm comm, bool precondition = true)
      : w0_(initialRelaxation), reuse_(reuse), filter_(filter), comm_(comm), qr_(comm), precondition_(precondition) {}
  Eigen::VectorXd performAcceleration(const Eigen::VectorXd& x, const Eigen::VectorXd& xt) override;
  void iterationsConverged() override;
  void setSegments(const std::vector<Segment>& segments) override;
  const char* name() const override { return "iqn_ils"; }
  void save(core::CheckpointData& data, const std::string& prefix) const override;  // acceleration_checkpoint.cpp
  void load(const core::CheckpointData& data, const std::string& prefix) override;
  /// Columns used in the last least-squares solve (after filtering).
  [[nodiscard]] int columnsUsed() const { return used_; }
  /// Times the QR was rebuilt (preconditioner weights renewed with columns in use).
  [[nodiscard]] int rebuilds() const { return rebuilds_; }
  /// The preconditioner's weight of each segment group (empty without segments).
  [[nodiscard]] const std::vector<double>& weights() const { return groupWeight_; }

 private:
  struct Column {
    Eigen::VectorXd v, w;
    double norm = 0;  // || P v ||
    int age = 0;      // steps since the step that made it
  };
  [[nodiscard]] Eigen::VectorXd scaled(const Eigen::VectorXd& v) const;
  void insert(Column c);
  void filter();
  void accumulateResidual(const Eigen::VectorXd& r);
  [[nodiscard]] std::vector<double> proposedWeights() const;
  void adopt(const std::vector<double>& w);

  double w0_;
  int reuse_;
  double filter_;
  core::Comm comm_;
  QrFactorization qr_;
  std::deque<Column> cols_;  // newest first: the QR's columns
  Eigen::VectorXd rPrev_, xtPrev_;
  bool havePrev_ = false;
  int used_ = 0, rebuilds_ = 0;
  bool precondition_;
  std::vector<Segment> segments_;
  std::vector<double> groupWeight_, residualShare_;
  Eigen::VectorXd weight_;  // per element (empty: 1)
};

}  // namespace mpmice::coupler
