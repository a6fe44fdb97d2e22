#pragma once
/// @brief The cell-centred fields that cross between the solid and the fluid side in one MPM-ICE
/// step (monolithic-style schedule, four exchange points), one set per solid material.
///
///   A  solid -> fluid  mass, velocity (3), temperature, specific volume      after particle-to-grid
///   B  fluid -> solid  pressure force on the solid (3) [N], cell pressure [Pa]   after the face pressure
///   C  solid -> fluid  Lagrangian momentum of the solid (3) [kg m/s]            after the grid update
///   D  fluid -> solid  exchange increments of the solid: momentum (3) [kg m/s], energy [J]
/// Every field covers the owned cells of its side's rank, component-major, no ghosts.
#include <string>
#include <vector>

#include "core/field/field.h"

namespace mpmice::coupler {

struct SolidExchangeFields {
  int material = -1;           // scene index of the solid
  std::string name;
  core::Field mass, velocity, temperature, specificVolume;  // A
  core::Field pressureForce, pressure;                      // B
  core::Field lagrangianMomentum;                           // C
  core::Field exchangeMomentum, exchangeEnergy;             // D

  SolidExchangeFields(int m, const std::string& n, const core::Box& owned);
  [[nodiscard]] std::vector<const core::Field*> a() const { return {&mass, &velocity, &temperature, &specificVolume}; }
  [[nodiscard]] std::vector<core::Field*> a() { return {&mass, &velocity, &temperature, &specificVolume}; }
  [[nodiscard]] std::vector<const core::Field*> b() const { return {&pressureForce, &pressure}; }
  [[nodiscard]] std::vector<core::Field*> b() { return {&pressureForce, &pressure}; }
  [[nodiscard]] std::vector<const core::Field*> d() const { return {&exchangeMomentum, &exchangeEnergy}; }
  [[nodiscard]] std::vector<core::Field*> d() { return {&exchangeMomentum, &exchangeEnergy}; }
};

/// Exchange tags of the four points (distinct per solid: tag + 8 * solid slot).
enum ExchangeTag : int { kTagA = 101, kTagB = 102, kTagC = 103, kTagD = 104, kTagScalars = 105 };

}  // namespace mpmice::coupler
