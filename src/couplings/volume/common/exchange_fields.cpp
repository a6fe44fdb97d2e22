#include "couplings/volume/common/exchange_fields.h"

#include <span>

namespace mpmice::coupler {

SolidExchangeFields::SolidExchangeFields(int m, const std::string& n, const core::Box& owned)
    : material(m), name(n),
      mass(n + "/mass", core::Centering::Cell, owned, 1, 0),
      velocity(n + "/velocity", core::Centering::Cell, owned, 3, 0),
      temperature(n + "/temperature", core::Centering::Cell, owned, 1, 0),
      specificVolume(n + "/specific_volume", core::Centering::Cell, owned, 1, 0),
      faceDensity(n + "/face_density", core::Centering::Cell, owned, 3, 0),
      faceFlux(n + "/face_flux", core::Centering::Cell, owned, 3, 0),
      pressureForce(n + "/pressure_force", core::Centering::Cell, owned, 3, 0),
      pressure(n + "/pressure", core::Centering::Cell, owned, 1, 0),
      lagrangianMomentum(n + "/lagrangian_momentum", core::Centering::Cell, owned, 3, 0),
      couplingWork(n + "/coupling_work", core::Centering::Cell, owned, 1, 0),
      volumeChange(n + "/volume_change", core::Centering::Cell, owned, 1, 0),
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
    case ExchangePoint::SolidState: return {&mass, &velocity, &temperature, &specificVolume, &faceDensity, &faceFlux};
    case ExchangePoint::PressureForce: return {&pressureForce, &pressure};
    case ExchangePoint::LagrangianMomentum: return {&lagrangianMomentum, &couplingWork, &volumeChange};
    case ExchangePoint::ExchangeIncrements: return {&exchangeMomentum, &exchangeEnergy};
  }
  return {};
}

std::vector<const core::Field*> SolidExchangeFields::at(ExchangePoint p) const {
  const auto fields = const_cast<SolidExchangeFields*>(this)->at(p);
  return {fields.begin(), fields.end()};
}

namespace {
template <class Fields, class F>
void forEachExchangeField(Fields& fields, const std::string& prefix, F&& f) {
  for (std::size_t k = 0; k < fields.size(); ++k)
    for (ExchangePoint p : kExchangePoints) {
      const auto at = fields[k].at(p);
      for (std::size_t i = 0; i < at.size(); ++i) {
        std::string name = prefix;
        name += ".s" + std::to_string(k) + ".p" + std::to_string(static_cast<int>(p)) + "." + std::to_string(i);
        f(name, *at[i]);
      }
    }
}
}  // namespace

void saveExchangeFields(const std::vector<SolidExchangeFields>& fields, core::CheckpointData& data,
                        const std::string& prefix) {
  forEachExchangeField(fields, prefix, [&](const std::string& name, const core::Field& f) {
    data.put(name, std::span<const double>(f.data(), static_cast<std::size_t>(f.npts() * f.ncomp())));
  });
}

void loadExchangeFields(std::vector<SolidExchangeFields>& fields, const core::CheckpointData& data,
                        const std::string& prefix) {
  forEachExchangeField(fields, prefix, [&](const std::string& name, core::Field& f) {
    data.copyTo(name, std::span<double>(f.data(), static_cast<std::size_t>(f.npts() * f.ncomp())));
  });
}

}  // namespace mpmice::coupler
