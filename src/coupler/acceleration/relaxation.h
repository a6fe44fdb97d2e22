#pragma once
/// @brief Under-relaxation accelerations: none, constant and Aitken's dynamic relaxation.
#include "coupler/acceleration/acceleration.h"

namespace mpmice::coupler {

class ConstantRelaxation final : public Acceleration {
 public:
  explicit ConstantRelaxation(double w) : w_(w) {}
  Eigen::VectorXd performAcceleration(const Eigen::VectorXd& x, const Eigen::VectorXd& xt) override {
    return x + w_ * (xt - x);
  }
  void iterationsConverged() override {}
  const char* name() const override { return w_ == 1.0 ? "none" : "constant"; }

 private:
  double w_;
};

/// Aitken: w_k = -w_{k-1} (r_{k-1} . (r_k - r_{k-1})) / ||r_k - r_{k-1}||^2; the first
/// iteration of every step uses the initial relaxation (bounded by the previous step's last).
class AitkenRelaxation final : public Acceleration {
 public:
  AitkenRelaxation(double initial, core::Comm comm) : initial_(initial), comm_(comm) {}
  Eigen::VectorXd performAcceleration(const Eigen::VectorXd& x, const Eigen::VectorXd& xt) override;
  void iterationsConverged() override { first_ = true; }
  const char* name() const override { return "aitken"; }
  void save(core::CheckpointData& data, const std::string& prefix) const override;  // acceleration_checkpoint.cpp
  void load(const core::CheckpointData& data, const std::string& prefix) override;
  [[nodiscard]] double relaxation() const { return w_; }

 private:
  double initial_;
  core::Comm comm_;
  double w_ = 0;
  bool first_ = true;
  Eigen::VectorXd rPrev_;
};

}  // namespace mpmice::coupler
