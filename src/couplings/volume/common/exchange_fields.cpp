#include "couplings/volume/common/exchange_fields.h"

namespace mpmice::coupler {

SolidExchangeFields::SolidExchangeFields(int m, const std::string& n, const core::Box& owned)
    : material(m), name(n),
      mass(n + "/mass", core::Centering::Cell, owned, 1, 0),
      velocity(n + "/velocity", core::Centering::Cell, owned, 3, 0),
      temperature(n + "/temperature", core::Centering::Cell, owned, 1, 0),
      specificVolume(n + "/specific_volume", core::Centering::Cell, owned, 1, 0),
      pressureForce(n + "/pressure_force", core::Centering::Cell, owned, 3, 0),
      pressure(n + "/pressure", core::Centering::Cell, owned, 1, 0),
      lagrangianMomentum(n + "/lagrangian_momentum", core::Centering::Cell, owned, 3, 0),
      exchangeMomentum(n + "/exchange_momentum", core::Centering::Cell, owned, 3, 0),
      exchangeEnergy(n + "/exchange_energy", core::Centering::Cell, owned, 1, 0) {}

}  // namespace mpmice::coupler
