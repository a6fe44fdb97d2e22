#pragma once
/// @brief The seed's monolithic-style step across the two sides: four exchange points in the
/// step (solid state, pressure force, Lagrangian momentum, exchange increments).
#include "couplings/volume/schedule/coupling_schedule.h"

namespace mpmice::coupler {

class MonolithicStyleSchedule final : public CouplingSchedule {
 public:
  StepReport step(const Sides& sides, Transport& transport, double dt) override;
  [[nodiscard]] core::Schedule kind() const override { return core::Schedule::Monolithic; }
};

}  // namespace mpmice::coupler
