#include "couplings/volume/schedule/sides.h"

namespace mpmice::coupler {

std::size_t Sides::solids() const { return solid ? solid->fields().size() : fluid ? fluid->fields().size() : 0; }

void exchange(const Sides& sides, Transport& transport, ExchangePoint p, const std::string& when) {
  const bool solidProduces = producedBySolid(p);
  for (std::size_t s = 0; s < sides.solids(); ++s) {
    std::vector<const core::Field*> from;
    std::vector<core::Field*> to;
    SolidSide* producerSolid = solidProduces ? sides.solid : nullptr;
    FluidSide* producerFluid = solidProduces ? nullptr : sides.fluid;
    if (producerSolid) from = std::as_const(producerSolid->fields()[s]).at(p);
    if (producerFluid) from = std::as_const(producerFluid->fields()[s]).at(p);
    if (solidProduces && sides.fluid) to = sides.fluid->fields()[s].at(p);
    if (!solidProduces && sides.solid) to = sides.solid->fields()[s].at(p);
    const std::string name = sides.solid ? sides.solid->fields()[s].name : sides.fluid->fields()[s].name;
    std::string what = std::string(describe(p)) + " of " + name;
    if (!when.empty()) what += " (" + when + ")";
    transport.move(from, to, exchangeTag(p, static_cast<int>(s)), what);
  }
}

}  // namespace mpmice::coupler
