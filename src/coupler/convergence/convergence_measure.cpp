#include "coupler/convergence/convergence_measure.h"

#include <cmath>
#include <stdexcept>

namespace mpmice::coupler {

double globalNorm(const Eigen::VectorXd& v, const core::Comm& comm) {
  return std::sqrt(comm.sum(v.squaredNorm()));
}

namespace {

class AbsoluteMeasure final : public ConvergenceMeasure {
 public:
  explicit AbsoluteMeasure(double limit) : limit_(limit) {}
  bool measure(const Eigen::VectorXd& o, const Eigen::VectorXd& n, const core::Comm& comm) override {
    residual_ = globalNorm(n - o, comm);
    threshold_ = limit_;
    return residual_ <= threshold_;
  }
  const char* name() const override { return "absolute"; }

 private:
  double limit_;
};

class RelativeMeasure final : public ConvergenceMeasure {
 public:
  explicit RelativeMeasure(double limit) : limit_(limit) {}
  bool measure(const Eigen::VectorXd& o, const Eigen::VectorXd& n, const core::Comm& comm) override {
    residual_ = globalNorm(n - o, comm);
    threshold_ = limit_ * globalNorm(n, comm);
    return residual_ <= threshold_;
  }
  const char* name() const override { return "relative"; }

 private:
  double limit_;
};

class ResidualRelativeMeasure final : public ConvergenceMeasure {
 public:
  explicit ResidualRelativeMeasure(double limit) : limit_(limit) {}
  void newStep() override { first_ = -1; }
  bool measure(const Eigen::VectorXd& o, const Eigen::VectorXd& n, const core::Comm& comm) override {
    residual_ = globalNorm(n - o, comm);
    if (first_ < 0) first_ = residual_;
    threshold_ = limit_ * first_;
    // A step whose first residual is already zero has converged.
    return residual_ <= threshold_;
  }
  const char* name() const override { return "residual_relative"; }

 private:
  double limit_;
  double first_ = -1;
};

}  // namespace

const std::vector<std::string>& convergenceMeasureNames() {
  static const std::vector<std::string> names{"absolute", "relative", "residual_relative"};
  return names;
}

std::unique_ptr<ConvergenceMeasure> makeConvergenceMeasure(const std::string& type, double limit) {
  if (!(limit > 0)) throw std::invalid_argument("convergence limit must be > 0, got " + std::to_string(limit));
  if (type == "absolute") return std::make_unique<AbsoluteMeasure>(limit);
  if (type == "relative") return std::make_unique<RelativeMeasure>(limit);
  if (type == "residual_relative") return std::make_unique<ResidualRelativeMeasure>(limit);
  throw std::invalid_argument("unknown convergence measure '" + type +
                              "'; valid: absolute, relative, residual_relative");
}

}  // namespace mpmice::coupler
