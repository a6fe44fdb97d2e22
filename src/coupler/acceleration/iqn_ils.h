#pragma once
/// @brief IQN-ILS: interface quasi-Newton with an inverse Jacobian from least squares.
///
/// Columns V (differences of residuals r = x~ - x) and W (differences of outputs x~) are kept
/// over the iterations of the current step and of up to `reuse` past steps. The next input is
///   x^{k+1} = x~^k + W a,   a = argmin || V a + r^k ||,
/// solved through a QR factorisation of V built by modified Gram-Schmidt with global inner
/// products (the data are distributed). The QR filter drops a column whose component
/// orthogonal to the others is below `filter` times its norm (near-linear dependence), oldest
/// first. Without columns (the first iteration) it relaxes with the initial relaxation.
#include <deque>

#include "coupler/acceleration/acceleration.h"

namespace mpmice::coupler {

class IqnIls final : public Acceleration {
 public:
  IqnIls(double initialRelaxation, int reuse, double filter, core::Comm comm)
      : w0_(initialRelaxation), reuse_(reuse), filter_(filter), comm_(comm) {}
  Eigen::VectorXd performAcceleration(const Eigen::VectorXd& x, const Eigen::VectorXd& xt) override;
  void iterationsConverged() override;
  const char* name() const override { return "iqn_ils"; }
  /// Columns used in the last least-squares solve (after filtering).
  [[nodiscard]] int columnsUsed() const { return used_; }

 private:
  struct Column {
    Eigen::VectorXd v, w;
  };
  double w0_;
  int reuse_;
  double filter_;
  core::Comm comm_;
  std::deque<Column> current_;               // this step, newest first
  std::deque<std::deque<Column>> past_;      // past steps, newest first
  Eigen::VectorXd rPrev_, xtPrev_;
  bool havePrev_ = false;
  int used_ = 0;
};

}  // namespace mpmice::coupler
