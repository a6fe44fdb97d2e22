#include "couplings/volume/common/implicit_iteration.h"

#include <sstream>
#include <stdexcept>

namespace mpmice::coupler {

namespace {
bool isFluidOutput(const std::string& f) { return f == "pressure_force" || f == "pressure" || f == "exchange_momentum"; }
}  // namespace

ImplicitIteration::ImplicitIteration(const core::CouplingSpec& spec, const core::Comm& comm, bool parallel)
    : spec_(spec), comm_(comm), parallel_(parallel) {
  std::vector<core::ConvergenceSpec> conv = spec.convergence;
  if (conv.empty()) {
    for (const std::string f : {"pressure_force", "exchange_momentum"}) conv.push_back({f, "relative", 1e-6, true});
    if (parallel) conv.push_back({"solid_velocity", "relative", 1e-6, true});
  }
  for (const auto& c : conv) {
    if (!parallel_ && !isFluidOutput(c.field))
      throw std::invalid_argument("coupling.convergence: field '" + c.field + "' is not iterated by implicit_serial; "
                                  "valid: pressure_force, pressure, exchange_momentum (or use implicit_parallel)");
    measures_.push_back({c.field, c.strict, makeConvergenceMeasure(c.type, c.limit)});
  }
  AccelerationParams a;
  a.type = spec.acceleration.type;
  a.relaxation = spec.acceleration.relaxation;
  a.reuse = spec.acceleration.reuse;
  a.filter = spec.acceleration.filter;
  acceleration_ = makeAcceleration(a, comm);
}

std::vector<std::string> ImplicitIteration::measuredFields() const {
  std::vector<std::string> n;
  for (const auto& m : measures_) n.push_back(m.field);
  return n;
}

std::vector<std::pair<std::string, core::Field*>> ImplicitIteration::iterated(std::vector<SolidExchangeFields>& f) const {
  std::vector<std::pair<std::string, core::Field*>> out;
  for (auto& s : f) {
    if (parallel_) {
      out.emplace_back("solid_mass", &s.mass);
      out.emplace_back("solid_velocity", &s.velocity);
      out.emplace_back("solid_temperature", &s.temperature);
      out.emplace_back("solid_specific_volume", &s.specificVolume);
      out.emplace_back("lagrangian_momentum", &s.lagrangianMomentum);
    }
    out.emplace_back("pressure_force", &s.pressureForce);
    out.emplace_back("pressure", &s.pressure);
    out.emplace_back("exchange_momentum", &s.exchangeMomentum);
    out.emplace_back("exchange_energy", &s.exchangeEnergy);
  }
  return out;
}

Eigen::VectorXd ImplicitIteration::pack(std::vector<SolidExchangeFields>& f) const {
  std::vector<double> v;
  for (const auto& [name, field] : iterated(f)) {
    v.insert(v.end(), field->data(), field->data() + field->npts() * field->ncomp());
  }
  return Eigen::Map<Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

void ImplicitIteration::unpack(const Eigen::VectorXd& x, std::vector<SolidExchangeFields>& f) const {
  Eigen::Index o = 0;
  for (const auto& [name, field] : iterated(f)) {
    const auto n = static_cast<Eigen::Index>(field->npts() * field->ncomp());
    std::copy(x.data() + o, x.data() + o + n, field->data());
    o += n;
  }
}

StepReport ImplicitIteration::iterate(std::vector<SolidExchangeFields>& sf, double t0,
                                     const std::function<void(bool)>& pass, const std::function<void()>& restore,
                                     const std::function<void(bool)>& verdict) {
  const bool serialOrder = !parallel_ || first_;
  auto fieldOf = [&](const Eigen::VectorXd& x, const std::string& name) {
    std::vector<double> v;
    Eigen::Index o = 0;
    for (const auto& [n, field] : iterated(sf)) {
      const auto len = static_cast<Eigen::Index>(field->npts() * field->ncomp());
      if (n == name) v.insert(v.end(), x.data() + o, x.data() + o + len);
      o += len;
    }
    return Eigen::Map<Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size())).eval();
  };

  for (auto& m : measures_) m.measure->newStep();
  Eigen::VectorXd x = pack(sf);
  StepReport report;
  for (int k = 1;; ++k) {
    unpack(x, sf);
    pass(serialOrder);
    const Eigen::VectorXd xt = pack(sf);
    bool allStrict = true, anySuffices = false, anyStrict = false;
    report.residuals.clear();
    for (auto& m : measures_) {
      const bool ok = m.measure->measure(fieldOf(x, m.field), fieldOf(xt, m.field), comm_);
      report.residuals.push_back(m.measure->residual());
      if (m.strict) {
        anyStrict = true;
        allStrict = allStrict && ok;
      } else {
        anySuffices = anySuffices || ok;
      }
    }
    const bool converged = k >= spec_.min_iterations && ((anyStrict && allStrict) || anySuffices);
    report.iterations = k;
    const bool done = converged || k >= spec_.max_iterations;
    report.converged = converged;
    if (done && !converged && !spec_.accept_unconverged) {
      std::ostringstream os;
      os << "coupling: the step at t = " << t0 << " did not converge in " << spec_.max_iterations
         << " iterations (coupling.max_iterations); residuals:";
      for (std::size_t i = 0; i < measures_.size(); ++i)
        os << " " << measures_[i].field << " " << report.residuals[i] << " (limit "
           << measures_[i].measure->threshold() << ")";
      os << ". Raise max_iterations, relax the limits, add acceleration, or set accept_unconverged: true";
      throw std::runtime_error(os.str());
    }
    verdict(done);
    if (done) {
      acceleration_->iterationsConverged();
      first_ = false;
      return report;  // sf holds this step's output: the next step's input
    }
    restore();
    x = acceleration_->performAcceleration(x, xt);
  }
}

}  // namespace mpmice::coupler
