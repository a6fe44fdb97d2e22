#include "coupler/iteration/implicit_iteration.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "coupler/iteration/acceptance.h"

namespace mpmice::coupler {

Eigen::VectorXd gather(const std::vector<DataView>& views, const std::string& name) {
  std::size_t n = 0;
  for (const auto& v : views)
    if (v.name == name) n += v.values.size();
  Eigen::VectorXd out(static_cast<Eigen::Index>(n));
  Eigen::Index o = 0;
  for (const auto& v : views)
    if (v.name == name)
      for (double x : v.values) out[o++] = x;
  return out;
}

Eigen::VectorXd pack(const std::vector<DataView>& views) {
  std::size_t n = 0;
  for (const auto& v : views) n += v.values.size();
  Eigen::VectorXd out(static_cast<Eigen::Index>(n));
  Eigen::Index o = 0;
  for (const auto& v : views)
    for (double x : v.values) out[o++] = x;
  return out;
}

void unpack(const Eigen::VectorXd& x, const std::vector<DataView>& views) {
  Eigen::Index o = 0;
  for (const auto& v : views)
    for (double& y : v.values) y = x[o++];
}

ImplicitIteration::ImplicitIteration(const core::CouplingSpec& spec, std::vector<core::ConvergenceSpec> measures,
                                     const core::Comm& comm)
    : spec_(spec), comm_(comm) {
  for (auto& c : measures) {
    auto m = makeConvergenceMeasure(std::string(core::name(c.type)), c.limit);
    measures_.push_back({std::move(c), std::move(m)});
  }
  AccelerationParams a;
  a.type = std::string(core::name(spec.acceleration.type));
  a.relaxation = spec.acceleration.relaxation;
  a.reuse = spec.acceleration.reuse;
  a.filter = spec.acceleration.filter;
  a.precondition = spec.acceleration.preconditioner;
  acceleration_ = makeAcceleration(a, comm);
}

std::vector<std::string> ImplicitIteration::measuredFields() const {
  std::vector<std::string> n;
  for (const auto& m : measures_) n.push_back(m.spec.field);
  return n;
}

void ImplicitIteration::beginStep() {
  for (auto& m : measures_) m.measure->newStep();
}

bool ImplicitIteration::judge(int k, const std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>>& values,
                              const std::string& when, StepReport& report) {
  if (values.size() != measures_.size()) throw std::logic_error("ImplicitIteration::judge: one pair per measure");
  std::vector<MeasureOutcome> outcomes;
  report.residuals.clear();
  for (std::size_t i = 0; i < measures_.size(); ++i) {
    auto& m = measures_[i];
    const bool measurable = values[i].first.size() > 0;
    const bool holds = measurable && m.measure->measure(values[i].first, values[i].second, comm_);
    outcomes.push_back({holds, m.spec.strict});
    report.residuals.push_back(m.measure->residual());
  }
  report.iterations = k;
  report.converged = stepAccepted(k, spec_.min_iterations, outcomes);
  const bool done = report.converged || k >= spec_.max_iterations;
  if (done && !report.converged && !spec_.accept_unconverged) {
    std::ostringstream os;
    os << "coupling: " << when << " did not converge in " << spec_.max_iterations
       << " iterations (coupling.max_iterations); residuals:";
    for (std::size_t i = 0; i < measures_.size(); ++i)
      os << " " << measures_[i].spec.field << " " << report.residuals[i] << " (limit "
         << measures_[i].measure->threshold() << (measures_[i].spec.strict ? ", strict" : ", suffices") << ")";
    os << ". Raise coupling.max_iterations, relax coupling.convergence, add coupling.acceleration, or set "
          "coupling.accept_unconverged: true";
    throw std::runtime_error(os.str());
  }
  return done;
}

Eigen::VectorXd ImplicitIteration::accelerate(const Eigen::VectorXd& x, const Eigen::VectorXd& xTilde) {
  return acceleration_->performAcceleration(x, xTilde);
}

void ImplicitIteration::endStep() { acceleration_->iterationsConverged(); }

StepReport ImplicitIteration::iterate(const std::vector<DataView>& views, const std::string& when,
                                      const std::function<void()>& pass, const std::function<void()>& restore,
                                      const std::function<void(bool)>& verdict) {
  beginStep();
  // The iterate's layout for the acceleration's preconditioner: one group per field name.
  std::vector<Segment> segments;
  std::vector<std::string> names;
  Eigen::Index offset = 0;
  for (const auto& v : views) {
    const auto at = std::find(names.begin(), names.end(), v.name);
    const int group = static_cast<int>(at - names.begin());
    if (at == names.end()) names.push_back(v.name);
    const auto n = static_cast<Eigen::Index>(v.values.size());
    segments.push_back({offset, n, group});
    offset += n;
  }
  acceleration_->setSegments(segments);
  Eigen::VectorXd x = pack(views);
  StepReport report;
  for (int k = 1;; ++k) {
    unpack(x, views);
    pass();
    const Eigen::VectorXd xt = pack(views);
    std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> values;
    if (!measures_.empty()) {
      unpack(x, views);
      for (const auto& m : measures_) values.emplace_back(gather(views, m.spec.field), Eigen::VectorXd());
      unpack(xt, views);
      for (std::size_t i = 0; i < measures_.size(); ++i) values[i].second = gather(views, measures_[i].spec.field);
    }
    const bool done = judge(k, values, when, report);
    verdict(done);
    if (done) {
      endStep();
      return report;  // the views hold this step's output: the next step's input
    }
    restore();
    x = accelerate(x, xt);
  }
}

}  // namespace mpmice::coupler
