#include "core/health/health.h"

#include <sstream>

namespace mpmice::core {

void stopOnViolation(const Comm& comm, const std::string& violation) {
  const std::string first = comm.firstMessage(violation);
  if (!first.empty()) throw HealthError(first, comm.root());
}

std::string formatPoint(const double* x, int dim) {
  std::ostringstream os;
  os.precision(6);
  os << "(";
  for (int d = 0; d < dim; ++d) os << (d ? ", " : "") << x[d];
  os << ")";
  return os.str();
}

std::string StepCollapse::message(double stable, double t, long step, const std::string& limit) const {
  std::ostringstream os;
  os.precision(6);
  os << "time step collapsed: the stable step " << stable << " s at t = " << t << " s (step " << step
     << ") is below time.dt_collapse_fraction = " << fraction_ << " of the run's first stable step " << first_
     << " s (lower the key, or set it to 0, to let the run go on); the step was set by " << limit;
  return os.str();
}

}  // namespace mpmice::core
