#pragma once
/// @brief The cell-centred fields that cross between the solid and the fluid side in one MPM-ICE
/// step, one set per solid material, grouped by the exchange point that carries them.
///
///   exchange point         direction        fields                                      after
///   SolidState             solid -> fluid   mass, velocity (3), temperature,            particle-to-grid
///                                           specific volume, and with coupling.solid_transport
///                                           mpm the face transport of the solid's mass at each
///                                           cell's low face per direction: face density (3)
///                                           [kg/m^3] and face mass flux (3) [kg/(m^2 s)]
///   PressureForce          fluid -> solid   pressure force on the solid (3) [N],       the face pressure
///                                           cell pressure [Pa]
///   LagrangianMomentum     solid -> fluid   Lagrangian momentum of the solid (3)        the grid update
///                                           [kg m/s], the work the fluid's forces did
///                                           on it in the grid update [J], the solid's
///                                           volume change over the step [m^3] (its
///                                           velocity gradient on its particles' volumes)
///   ExchangeIncrements     fluid -> solid   exchange increments of the solid:           the exchange
///                                           momentum (3) [kg m/s], energy [J]
/// Every field covers the owned cells of its side's rank, component-major, no ghosts.
#include <array>
#include <string>
#include <vector>

#include "core/field/field.h"
#include "core/io/checkpoint.h"

namespace mpmice::coupler {

enum class ExchangePoint { SolidState, PressureForce, LagrangianMomentum, ExchangeIncrements };
inline constexpr std::array<ExchangePoint, 4> kExchangePoints{ExchangePoint::SolidState, ExchangePoint::PressureForce,
                                                              ExchangePoint::LagrangianMomentum,
                                                              ExchangePoint::ExchangeIncrements};

/// Words for logs and timeout messages: "solid state", "pressure force", ...
const char* describe(ExchangePoint p);
/// True for the points the solid produces (SolidState, LagrangianMomentum).
constexpr bool producedBySolid(ExchangePoint p) {
  return p == ExchangePoint::SolidState || p == ExchangePoint::LagrangianMomentum;
}
/// The message tag of a point for the solid in `slot` (distinct per point and solid).
constexpr int exchangeTag(ExchangePoint p, int slot) { return 101 + static_cast<int>(p) + 8 * slot; }

struct SolidExchangeFields {
  int material = -1;           // scene index of the solid
  std::string name;
  core::Field mass, velocity, temperature, specificVolume;  // SolidState
  core::Field faceDensity, faceFlux;                         // SolidState (solid_transport mpm)
  core::Field pressureForce, pressure;                      // PressureForce
  core::Field lagrangianMomentum, couplingWork, volumeChange;  // LagrangianMomentum
  core::Field exchangeMomentum, exchangeEnergy;             // ExchangeIncrements

  SolidExchangeFields(int m, const std::string& n, const core::Box& owned);
  /// The fields one exchange point carries, in their order on the wire.
  [[nodiscard]] std::vector<core::Field*> at(ExchangePoint p);
  [[nodiscard]] std::vector<const core::Field*> at(ExchangePoint p) const;
};

/// Every exchange field of every solid under `prefix` (a side's held values: a partitioned
/// schedule starts a step from the other side's last ones), for a checkpoint; load puts them back.
void saveExchangeFields(const std::vector<SolidExchangeFields>& fields, core::CheckpointData& data,
                        const std::string& prefix);
void loadExchangeFields(std::vector<SolidExchangeFields>& fields, const core::CheckpointData& data,
                        const std::string& prefix);

}  // namespace mpmice::coupler
