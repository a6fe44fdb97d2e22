#pragma once
/// @brief Only what a scene needs crosses: each side declares, from the scene, the fields it
/// reads and writes at each exchange point; the two declarations are agreed at start-up and
/// what travels is what the consumer reads.
///
/// A declaration gives, per exchange point, per solid (slot) and per field of that point (in the
/// order of SolidExchangeFields::at), how many of the field's components (its first ones) are
/// read or written; 0 is not at all. From the scene:
/// - the solid writes its cell state and Lagrangian momentum, vectors with the mesh's dim
///   components; it reads the pressure force of every solid (dim components), the cell pressure
///   once (the first solid's: the mean-stress correction uses one cell pressure for all solids),
///   the exchange momentum when some pair exchanges momentum, the exchange energy when some pair
///   exchanges momentum (its drag heat is shared by every material) or heat;
/// - the fluid reads the solids' cell state (temperature included: it sets the solid's internal
///   energy) and Lagrangian momentum with dim components, and writes every field of the pressure
///   force and exchange increment points.
/// agree() checks that what the consumer reads the producer writes (a mismatch is an error that
/// names both sides' lists) and returns what travels. A component or field that does not travel
/// keeps its value on the consumer (zero: the z components of a 2D run, which nobody reads).
#include <array>
#include <string>
#include <vector>

#include "core/scene/scene.h"
#include "couplings/volume/common/exchange_fields.h"

namespace mpmice::coupler {

/// Components per point, solid slot and field ([point][slot][field]).
struct FieldUses {
  std::array<std::vector<std::vector<int>>, 4> at;
  [[nodiscard]] const std::vector<int>& of(ExchangePoint p, std::size_t slot) const {
    return at[static_cast<std::size_t>(p)][slot];
  }
  [[nodiscard]] bool operator==(const FieldUses&) const = default;
  /// Doubles per owned cell that one move of every point carries (a step of the monolithic-style
  /// and explicit schedules moves each point once).
  [[nodiscard]] long valuesPerCell() const;
  /// Every field with every component: what crossed before declarations.
  static FieldUses everything(std::size_t solids);
};

struct ExchangeDeclaration {
  FieldUses reads, writes;
};

/// What each side declares for `scene`.
ExchangeDeclaration solidDeclaration(const core::Scene& scene);
ExchangeDeclaration fluidDeclaration(const core::Scene& scene);

/// What travels: the consumer's reads at every point. Throws HandshakeMismatch when a consumer
/// reads a field or component its producer does not write, naming the point and both lists.
/// The solids' names (for the messages) come from `scene`.
FieldUses agree(const core::Scene& scene, const ExchangeDeclaration& solid, const ExchangeDeclaration& fluid);

/// "steel: mass velocity(2) temperature specific_volume" (the fields of point p for one slot).
std::string describeUses(const std::vector<int>& components, ExchangePoint p, const std::string& solid);

/// Text form of a declaration (for the handshake) and back.
std::string encodeDeclaration(const ExchangeDeclaration& d);
ExchangeDeclaration decodeDeclaration(const std::string& text);

}  // namespace mpmice::coupler
