#pragma once
/// @brief The scene's named choices, parsed once into enums (the model families, shape
/// functions and update schemes are chosen by name through their registries instead).
///
/// Each enum has one table of its scene names (kScheduleNames, ...); the schema reads a name
/// through it (an unknown name is an error listing the valid ones), and name() turns a value
/// back into its scene name for logs, dumps and the handshake. Code switches on the enum
/// (-Wswitch catches a case a new value leaves out); nothing compares the strings again.
#include <array>
#include <string_view>
#include <utility>

namespace mpmice::core {

/// coupling.schedule: how one coupled step is taken (docs/coupling.md).
enum class Schedule { Monolithic, ExplicitSerial, ExplicitParallel, ImplicitSerial, ImplicitParallel };
/// coupling.fluid: the fluid side (ICE on the shared mesh, or OpenFOAM through the surface).
enum class FluidSolver { Ice, OpenFoam };
/// coupling.interface.mapping: between the solid's surface particles and the fluid's patch.
enum class InterfaceMapping { NearestNeighbor, Rbf };
/// coupling.interface.mode: forces and displacements both ways, or the fluid's forces once.
enum class CouplingMode { TwoWay, OneWay };

inline constexpr std::array<std::pair<Schedule, std::string_view>, 5> kScheduleNames{{
    {Schedule::Monolithic, "monolithic"},
    {Schedule::ExplicitSerial, "explicit_serial"},
    {Schedule::ExplicitParallel, "explicit_parallel"},
    {Schedule::ImplicitSerial, "implicit_serial"},
    {Schedule::ImplicitParallel, "implicit_parallel"},
}};
inline constexpr std::array<std::pair<FluidSolver, std::string_view>, 2> kFluidSolverNames{{
    {FluidSolver::Ice, "ice"},
    {FluidSolver::OpenFoam, "openfoam"},
}};
inline constexpr std::array<std::pair<InterfaceMapping, std::string_view>, 2> kInterfaceMappingNames{{
    {InterfaceMapping::NearestNeighbor, "nearest_neighbor"},
    {InterfaceMapping::Rbf, "rbf"},
}};
inline constexpr std::array<std::pair<CouplingMode, std::string_view>, 2> kCouplingModeNames{{
    {CouplingMode::TwoWay, "two_way"},
    {CouplingMode::OneWay, "one_way"},
}};

/// The scene name of a value (every value is in its table).
/// coupling.acceleration.type (coupler/acceleration/acceleration.h).
enum class AccelerationType { None, Constant, Aitken, IqnIls };
/// coupling.convergence[].type (coupler/convergence/convergence_measure.h).
enum class MeasureType { Absolute, Relative, ResidualRelative };
/// loads[].type: a pressure on a solid's surface, a traction, or point forces read from a file
/// (a fluid code's export, mapped onto the solid's surface particles).
enum class LoadType { Pressure, Traction, File };

inline constexpr std::array<std::pair<AccelerationType, std::string_view>, 4> kAccelerationNames{{
    {AccelerationType::None, "none"},
    {AccelerationType::Constant, "constant"},
    {AccelerationType::Aitken, "aitken"},
    {AccelerationType::IqnIls, "iqn_ils"},
}};
inline constexpr std::array<std::pair<MeasureType, std::string_view>, 3> kMeasureNames{{
    {MeasureType::Absolute, "absolute"},
    {MeasureType::Relative, "relative"},
    {MeasureType::ResidualRelative, "residual_relative"},
}};
inline constexpr std::array<std::pair<LoadType, std::string_view>, 3> kLoadNames{{
    {LoadType::Pressure, "pressure"},
    {LoadType::Traction, "traction"},
    {LoadType::File, "file"},
}};

template <class E, std::size_t N>
constexpr std::string_view nameIn(const std::array<std::pair<E, std::string_view>, N>& table, E e) {
  for (const auto& [v, n] : table)
    if (v == e) return n;
  return "?";
}
inline std::string_view name(Schedule s) { return nameIn(kScheduleNames, s); }
inline std::string_view name(FluidSolver f) { return nameIn(kFluidSolverNames, f); }
inline std::string_view name(InterfaceMapping m) { return nameIn(kInterfaceMappingNames, m); }
inline std::string_view name(CouplingMode m) { return nameIn(kCouplingModeNames, m); }
inline std::string_view name(AccelerationType a) { return nameIn(kAccelerationNames, a); }
inline std::string_view name(MeasureType m) { return nameIn(kMeasureNames, m); }
inline std::string_view name(LoadType l) { return nameIn(kLoadNames, l); }

/// Implicit schedules repeat a step until the acceptance checks pass; parallel ones let both
/// sides step from the other's last values.
constexpr bool isImplicit(Schedule s) { return s == Schedule::ImplicitSerial || s == Schedule::ImplicitParallel; }
constexpr bool isParallel(Schedule s) { return s == Schedule::ExplicitParallel || s == Schedule::ImplicitParallel; }

}  // namespace mpmice::core
