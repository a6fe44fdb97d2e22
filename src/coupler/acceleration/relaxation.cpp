#include "coupler/acceleration/relaxation.h"

#include <algorithm>
#include <cmath>

namespace mpmice::coupler {

Eigen::VectorXd AitkenRelaxation::performAcceleration(const Eigen::VectorXd& x, const Eigen::VectorXd& xt) {
  const Eigen::VectorXd r = xt - x;
  if (first_) {
    // preCICE's choice: the initial relaxation, bounded by the magnitude of the last one.
    w_ = (w_ == 0) ? initial_ : std::copysign(std::min(initial_, std::abs(w_)), w_);
    first_ = false;
  } else {
    const Eigen::VectorXd dr = r - rPrev_;
    const double num = comm_.sum(rPrev_.dot(dr));
    const double den = comm_.sum(dr.squaredNorm());
    if (den > 0) w_ = -w_ * num / den;
  }
  rPrev_ = r;
  return x + w_ * r;
}

}  // namespace mpmice::coupler
