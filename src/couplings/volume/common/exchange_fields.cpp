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
      couplingWork(n + "/coupling_work", core::Centering::Cell, owned, 1, 0),
      exchangeMomentum(n + "/exchange_momentum", core::Centering::Cell, owned, 3, 0),
      exchangeEnergy(n + "/exchange_energy", core::Centering::Cell, owned, 1, 0) {}

}  // namespace mpmice::coupler

namespace mpmice::coupler {

const char* describe(ExchangePoint p) {
  switch (p) {
    case ExchangePoint::SolidState: return "solid state";
    case ExchangePoint::PressureForce: return "pressure force";
    case ExchangePoint::LagrangianMomentum: return "Lagrangian momentum";
    case ExchangePoint::ExchangeIncrements: return "exchange increments";
  }
  return "?";
}

std::vector<core::Field*> SolidExchangeFields::at(ExchangePoint p) {
  switch (p) {
    case ExchangePoint::SolidState: return {&mass, &velocity, &temperature, &specificVolume};
    case ExchangePoint::PressureForce: return {&pressureForce, &pressure};
    case ExchangePoint::LagrangianMomentum: return {&lagrangianMomentum, &couplingWork};
    case ExchangePoint::ExchangeIncrements: return {&exchangeMomentum, &exchangeEnergy};
  }
  return {};
}

std::vector<const core::Field*> SolidExchangeFields::at(ExchangePoint p) const {
  const auto fields = const_cast<SolidExchangeFields*>(this)->at(p);
  return {fields.begin(), fields.end()};
}

}  // namespace mpmice::coupler
