#include "couplings/volume/schedule/sides.h"

namespace mpmice::coupler {

std::size_t Sides::solids() const { return solid ? solid->fields().size() : fluid ? fluid->fields().size() : 0; }

void exchange(const Sides& sides, Transport& transport, ExchangePoint p, const std::string& when) {
  const bool solidProduces = producedBySolid(p);
  for (std::size_t s = 0; s < sides.solids(); ++s) {
    SolidSide* producerSolid = solidProduces ? sides.solid : nullptr;
    FluidSide* producerFluid = solidProduces ? nullptr : sides.fluid;
    SolidExchangeFields& any = sides.solid ? sides.solid->fields()[s] : sides.fluid->fields()[s];
    const std::vector<core::Field*> fields = any.at(p);  // for the component counts
    std::vector<core::Field*> produced, consumed;
    if (producerSolid) produced = producerSolid->fields()[s].at(p);
    if (producerFluid) produced = producerFluid->fields()[s].at(p);
    if (solidProduces && sides.fluid) consumed = sides.fluid->fields()[s].at(p);
    if (!solidProduces && sides.solid) consumed = sides.solid->fields()[s].at(p);
    std::vector<const core::Field*> from;
    std::vector<core::Field*> to;
    std::vector<int> components;
    for (std::size_t i = 0; i < fields.size(); ++i) {
      const int c = sides.travel ? sides.travel->of(p, s)[i] : fields[i]->ncomp();
      if (c == 0) continue;  // nobody reads it
      components.push_back(c);
      if (!produced.empty()) from.push_back(produced[i]);
      if (!consumed.empty()) to.push_back(consumed[i]);
    }
    if (components.empty()) continue;
    std::string what = std::string(describe(p)) + " of " + any.name;
    if (!when.empty()) what += " (" + when + ")";
    transport.move(from, to, components, exchangeTag(p, static_cast<int>(s)), what);
  }
}

}  // namespace mpmice::coupler
