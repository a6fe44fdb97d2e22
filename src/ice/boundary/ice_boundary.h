#pragma once
/// @brief Boundary conditions of ICE on each mesh face, applied by filling ghost cells.
///
/// Per face (scene `boundary:`): symmetry and slip_wall mirror every field and negate the normal
/// velocity (so the face velocity is exactly zero); noslip_wall also negates the tangential
/// velocity; outflow (and free) copies the nearest cell (zero gradient) or, with a pressure, fixes
/// the pressure in the ghosts (and the increment to zero); inflow sets the entering material's
/// state (velocity, density or pressure and temperature) and zero fractions of the others.
/// Periodic directions are left to the ghost exchange. Only ranks whose cells touch the face act.
#include <array>
#include <vector>

#include "core/field/field.h"
#include "core/scene/scene.h"

namespace mpmice::ice {

/// What a field holds, which decides how a boundary fills its ghosts.
enum class FieldKind { Mass, Velocity, Energy, SpecificVolume, VolumeFraction, Pressure, Increment, Scalar };

/// Inflow state of one face, resolved per material by the solver.
struct InflowState {
  int material = 0;
  double rho = 0, e = 0, p = 0;   // rho: material density
  bool fixedPressure = false;
  core::RealVect velocity{0, 0, 0};
};

class IceBoundary {
 public:
  IceBoundary() = default;
  IceBoundary(const std::array<core::BoundarySpec, 6>& spec, const core::Mesh& mesh, const core::Box& owned,
              std::array<bool, 3> periodic, std::array<InflowState, 6> inflow);

  /// Fills the ghost layers of f on the domain faces this rank touches. `material` is the index
  /// of the material the field belongs to (-1 for shared fields).
  void apply(core::Field& f, FieldKind kind, int material) const;
  /// True when face side s (0..5) is an inflow this rank touches.
  [[nodiscard]] bool touches(int side) const { return touch_[side]; }
  [[nodiscard]] core::BoundaryType type(int side) const { return spec_[side].type; }
  [[nodiscard]] const InflowState& inflow(int side) const { return inflow_[side]; }
  /// True when the face fixes the pressure (inflow or outflow with a pressure).
  [[nodiscard]] bool fixedPressure(int side) const {
    return spec_[side].type == core::BoundaryType::Inflow ? inflow_[side].fixedPressure
                                                          : spec_[side].pressure.has_value();
  }

 private:
  std::array<core::BoundarySpec, 6> spec_;
  std::array<InflowState, 6> inflow_;
  std::array<bool, 6> touch_{};
  core::Box owned_;
  double cellVolume_ = 1;
  int dim_ = 1;
};

}  // namespace mpmice::ice
