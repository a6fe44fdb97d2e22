#include "couplings/volume/schedule/coupling_schedule.h"

#include <stdexcept>

#include "couplings/volume/schedule/explicit_schedules.h"
#include "couplings/volume/schedule/implicit_schedule.h"

namespace mpmice::coupler {

namespace {
std::vector<const core::Field*> point(const SolidExchangeFields& f, char p) {
  switch (p) {
    case 'A': return f.a();
    case 'B': return f.b();
    case 'C': return {&f.lagrangianMomentum};
    default: return f.d();
  }
}
std::vector<core::Field*> point(SolidExchangeFields& f, char p) {
  switch (p) {
    case 'A': return f.a();
    case 'B': return f.b();
    case 'C': return {&f.lagrangianMomentum};
    default: return f.d();
  }
}
}  // namespace

void transfer(const std::vector<SolidExchangeFields>& from, std::vector<SolidExchangeFields>& to, char p) {
  for (std::size_t s = 0; s < from.size(); ++s) {
    const auto src = point(from[s], p);
    const auto dst = point(to[s], p);
    for (std::size_t i = 0; i < src.size(); ++i) dst[i]->copyRegion(*src[i], src[i]->box(), dst[i]->box());
  }
}

const std::vector<std::string>& scheduleNames() {
  static const std::vector<std::string> names{"monolithic", "explicit_serial", "explicit_parallel",
                                              "implicit_serial", "implicit_parallel"};
  return names;
}

std::unique_ptr<CouplingSchedule> makeSchedule(const core::Scene& scene, const core::Comm& comm) {
  const std::string& n = scene.coupling.schedule;
  if (n == "monolithic") return std::make_unique<MonolithicStyleSchedule>();
  if (n == "explicit_serial") return std::make_unique<ExplicitSchedule>(false);
  if (n == "explicit_parallel") return std::make_unique<ExplicitSchedule>(true);
  if (n == "implicit_serial") return std::make_unique<ImplicitSchedule>(scene.coupling, comm, false);
  if (n == "implicit_parallel") return std::make_unique<ImplicitSchedule>(scene.coupling, comm, true);
  throw std::invalid_argument("coupling.schedule: unknown schedule '" + n +
                              "'; valid: monolithic, explicit_serial, explicit_parallel, implicit_serial, "
                              "implicit_parallel");
}

}  // namespace mpmice::coupler
