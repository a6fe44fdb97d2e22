#pragma once
/// @brief The two sides of an MPM-ICE step as one process sees them, and how an exchange point
/// moves between them.
///
/// The in-process driver holds both sides; an MPMD program holds one, and the other is absent
/// (null): it runs in the peer program, and the transport sends or receives its fields.
/// Schedules are written once against Sides and a Transport, so the same schedule object runs
/// in mpmice and in the MPMD programs.
#include <string>

#include "coupler/transport/transport.h"
#include "couplings/volume/common/exchange_declaration.h"
#include "couplings/volume/common/exchange_fields.h"
#include "couplings/volume/fluid/fluid_side.h"
#include "couplings/volume/solid/solid_side.h"

namespace mpmice::coupler {

struct Sides {
  SolidSide* solid = nullptr;
  FluidSide* fluid = nullptr;
  /// What travels at each point (the agreed declarations); null: every field and component.
  const FieldUses* travel = nullptr;
  [[nodiscard]] std::size_t solids() const;
};

/// Moves exchange point `p` of every solid from its producer to its consumer: the fields and
/// components of sides.travel (a solid with nothing to move there moves nothing). `when` is added
/// to the timeout messages ("initial", "iteration", ...).
void exchange(const Sides& sides, Transport& transport, ExchangePoint p, const std::string& when = "");

}  // namespace mpmice::coupler
