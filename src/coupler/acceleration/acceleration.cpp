#include "coupler/acceleration/acceleration.h"

#include <stdexcept>

#include "coupler/acceleration/iqn_ils.h"
#include "coupler/acceleration/relaxation.h"

namespace mpmice::coupler {

const std::vector<std::string>& accelerationNames() {
  static const std::vector<std::string> names{"none", "constant", "aitken", "iqn_ils"};
  return names;
}

std::unique_ptr<Acceleration> makeAcceleration(const AccelerationParams& p, const core::Comm& comm) {
  if (p.type != "none" && !(p.relaxation > 0 && p.relaxation <= 1))
    throw std::invalid_argument("coupling.acceleration.relaxation must be in (0, 1], got " +
                                std::to_string(p.relaxation));
  if (p.type == "none") return std::make_unique<ConstantRelaxation>(1.0);
  if (p.type == "constant") return std::make_unique<ConstantRelaxation>(p.relaxation);
  if (p.type == "aitken") return std::make_unique<AitkenRelaxation>(p.relaxation, comm);
  if (p.type == "iqn_ils") {
    if (p.reuse < 0) throw std::invalid_argument("coupling.acceleration.reuse must be >= 0");
    return std::make_unique<IqnIls>(p.relaxation, p.reuse, p.filter, comm, p.precondition);
  }
  throw std::invalid_argument("unknown coupling.acceleration.type '" + p.type +
                              "'; valid: none, constant, aitken, iqn_ils");
}

}  // namespace mpmice::coupler
