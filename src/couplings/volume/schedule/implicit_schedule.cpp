#include "couplings/volume/schedule/implicit_schedule.h"

#include <algorithm>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace mpmice::coupler {

namespace {
bool isFluidOutput(const std::string& f) { return f == "pressure_force" || f == "pressure" || f == "exchange_momentum"; }

std::span<double> all(core::Field& f) { return {f.data(), static_cast<std::size_t>(f.npts() * f.ncomp())}; }
/// A vector field's first `dim` components (contiguous: the field stores component by
/// component); the rest stay zero below 3D, so leaving them out of the iterate changes no sum.
std::span<double> vec(core::Field& f, int dim) {
  return {f.data(), static_cast<std::size_t>(f.npts() * std::min(f.ncomp(), dim))};
}
}  // namespace

std::vector<core::ConvergenceSpec> volumeMeasures(const core::CouplingSpec& spec) {
  const bool parallel = core::isParallel(spec.schedule);
  std::vector<core::ConvergenceSpec> conv = spec.convergence;
  if (conv.empty()) {
    for (const std::string f : {"pressure_force", "exchange_momentum"}) conv.push_back({f, core::MeasureType::Relative, 1e-6, true});
    if (parallel) conv.push_back({"solid_velocity", core::MeasureType::Relative, 1e-6, true});
  }
  for (const auto& c : conv)
    if (!parallel && !isFluidOutput(c.field))
      throw std::invalid_argument("coupling.convergence: field '" + c.field + "' is not iterated by implicit_serial; "
                                  "valid: pressure_force, pressure, exchange_momentum (or use implicit_parallel)");
  return conv;
}

ImplicitSchedule::ImplicitSchedule(const core::CouplingSpec& spec, const core::Comm& comm)
    : kind_(spec.schedule), iteration_(spec, volumeMeasures(spec), comm) {}

std::vector<DataView> ImplicitSchedule::iterate(SolidSide& solid) const {
  std::vector<DataView> v;
  const int dim = solid.solver().decomposition().mesh().dim();
  for (auto& s : solid.fields()) {
    if (core::isParallel(kind_)) {
      v.push_back({"solid_mass", all(s.mass)});
      v.push_back({"solid_velocity", vec(s.velocity, dim)});
      v.push_back({"solid_temperature", all(s.temperature)});
      v.push_back({"solid_specific_volume", all(s.specificVolume)});
      v.push_back({"lagrangian_momentum", vec(s.lagrangianMomentum, dim)});
    }
    v.push_back({"pressure_force", vec(s.pressureForce, dim)});
    v.push_back({"pressure", all(s.pressure)});
    v.push_back({"exchange_momentum", vec(s.exchangeMomentum, dim)});
    v.push_back({"exchange_energy", all(s.exchangeEnergy)});
  }
  return v;
}

StepReport ImplicitSchedule::step(const Sides& s, Transport& tr, double dt) {
  const bool serialOrder = !core::isParallel(kind_) || first_;
  first_ = false;
  std::optional<mpm::MpmSolver::Checkpoint> solidStart;
  std::optional<ice::IceSolver::Checkpoint> fluidStart;
  if (s.solid) solidStart = s.solid->solver().checkpoint();
  if (s.fluid) fluidStart = s.fluid->solver().checkpoint();
  // One pass: both sides step from the iterate; the fluid's output (and in parallel the
  // solid's) is the next x~.
  auto pass = [&] {
    if (!serialOrder) {
      exchange(s, tr, ExchangePoint::SolidState, "iteration");
      exchange(s, tr, ExchangePoint::LagrangianMomentum, "iteration");
    }
    if (s.solid) s.solid->fullStep(dt);
    if (serialOrder) {
      exchange(s, tr, ExchangePoint::SolidState, "iteration");
      exchange(s, tr, ExchangePoint::LagrangianMomentum, "iteration");
    }
    if (s.fluid) s.fluid->fullStep(dt);
    exchange(s, tr, ExchangePoint::PressureForce, "iteration");
    exchange(s, tr, ExchangePoint::ExchangeIncrements, "iteration");
  };
  auto restore = [&] {
    if (s.solid) s.solid->solver().restore(*solidStart);
    if (s.fluid) s.fluid->solver().restore(*fluidStart);
  };
  if (s.solid) {
    std::ostringstream when;
    when << "the step at t = " << s.solid->solver().time();
    auto verdict = [&](bool done) { tr.trade({done ? 1.0 : 0.0}, "verdict of the iteration"); };
    return iteration_.iterate(iterate(*s.solid), when.str(), pass, restore, verdict);
  }
  // A fluid side alone: the solid side iterates and decides.
  StepReport report;
  for (int k = 1;; ++k) {
    pass();
    report.iterations = k;
    if (tr.trade({0.0}, "verdict of the iteration")[0] != 0.0) return report;
    restore();
  }
}

}  // namespace mpmice::coupler
