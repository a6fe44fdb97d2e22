#pragma once
/// @brief The cell state of ICE: per-material SoA fields over this rank's cells plus ghosts.
///
/// Every material (fluid or external) has its mass per cell, velocity (the mesh's dimension of
/// components: 2D holds no z, which was an exact zero; core::components gives null beyond them;
/// output pads it to 3), specific internal energy, specific volume (1 / material
/// density) and volume fraction, and the Lagrangian (post-source, post-exchange) velocity,
/// energy and specific volume (a fluid's Lagrangian velocity and energy are its state fields
/// themselves, updated in place from the Lagrangian phase to the advection; an external
/// material's are copies, its state being its own solver's: lagVel, lagEint; the Lagrangian
/// specific volume takes kappa's array unless there are external materials: lagSpvol); face velocities live on the faces normal to each direction that
/// bound this rank's cells (face index i = low face of cell i). The pressure fields are shared by
/// all materials. Fields are stored over the owned box grown by kGhost layers.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "ice/eos/eos.h"
#include "core/field/components.h"
#include "core/field/field.h"

namespace mpmice::ice {

inline constexpr int kGhost = 2;

/// Specific volume of a material at a face: mass-weighted mean of the two cells (so a material
/// absent on one side takes the other side's value; one material: the harmonic mean of 1/rho).
inline double faceSpecificVolume(double mL, double vL, double mR, double vR) {
  const double m = mL + mR;
  return m > 0 ? (mL * vL + mR * vR) / m : 2.0 * vL * vR / (vL + vR);
}

struct MaterialState {
  std::string name;
  bool external = false;              // state supplied by another participant, not advected here
  std::unique_ptr<Eos> eos;
  double viscosity = 0, conductivity = 0;
  /// kappa = 1 / (rho^micro c^2), from the equilibrium to the Lagrangian phase (the exchange's
  /// trace rule with external materials reads it later).
  core::Field mass, vel, eint, spvol, theta, kappa;
  core::Field velL, eintL;  // Lagrangian velocity and energy of an external material (empty for a fluid)
  /// The Lagrangian specific volume apart, with external materials only (the exchange's trace
  /// rule reads it and kappa together); without them it is kappa's array (lagSpvol()): kappa's
  /// last reader, the Lagrangian phase, reads a cell's kappa before it writes its volume there.
  core::Field spvolL;
  /// A fluid's start-of-step internal energy and velocity, copied before the Lagrangian phase
  /// updates them in place, only where something after it reads them (the energy: heat
  /// conduction, and in coupled runs the embedded trace's temperature change; the velocity:
  /// viscosity, and the shock viscosity's stable step: its ghosts); empty otherwise.
  core::Field eintStart, velStart;
  /// Coupled runs: a fluid's temperature as the step found it (after the last step's advection,
  /// before this step's equilibrium pressure moved its volume), the start of the change the
  /// embedded-fluid rule measures (trace_temperature.cpp); empty otherwise.
  core::Field tempCycle;
  /// The Lagrangian velocity and internal energy (see above).
  core::Field& lagVel() { return external ? velL : vel; }
  const core::Field& lagVel() const { return external ? velL : vel; }
  core::Field& lagEint() { return external ? eintL : eint; }
  const core::Field& lagEint() const { return external ? eintL : eint; }
  /// The Lagrangian specific volume (see above).
  core::Field& lagSpvol() { return spvolL.npts() > 0 ? spvolL : kappa; }
  const core::Field& lagSpvol() const { return spvolL.npts() > 0 ? spvolL : kappa; }
  std::array<core::Field, 3> velFace;                // face velocity normal to each direction (empty beyond dim)
  core::Field dMom, dEnergy;          // exchange increments (external materials only; owned cells)
  core::Field couplingWork;           // work of the pressure forces on an external material [J] (owned)
  /// An external material's own volume change over the step [m^3] (owned), as its solver reports
  /// it (IceSolver::setExternalVolumeChange); `volumeChangeGiven` once it has been set.
  core::Field volumeChange;
  bool volumeChangeGiven = false;
  // External materials with a face transport (coupling.solid_transport mpm): at the low face of
  // each cell per direction, the face density [kg/m^3] and mass flux [kg/(m^2 s)] of the solid's
  // smeared mass as its own solver moves it (3 components; stored with ghosts). Empty otherwise.
  core::Field faceDensity, faceFlux;
};

/// The solids' face transport turned into ICE's face values (solid_faces.h), per direction on
/// the faces of the owned cells; `on` with coupling.solid_transport mpm.
struct SolidFaces {
  bool on = false;
  std::array<core::Field, 3> cover;    // fraction of the face the solids cover, in [0, kMaxSolidFraction]
  std::array<core::Field, 3> flux;     // the solids' volume flux [m/s] (volume per face area and time)
  std::array<core::Field, 3> inside;   // 1 where the face lies inside a solid (the fluids locked to it), else 0
};

struct IceState {
  std::vector<MaterialState> mat;
  /// Cell pressure: the equilibrium pressure of the step from the equilibrium phase to the pressure
  /// increment, which adds to it (the equilibrium pressure is not kept apart).
  core::Field press;
  core::Field dp;         // pressure increment: the semi-implicit solve's unknown (empty with the explicit pressure)
  /// Equilibrium iterations per stored cell (a diagnostic; the cell fields' indexing, press.box()),
  /// a count: 4 bytes, not a double; kept only where the output writes them (pressure_iterations),
  /// empty otherwise (IceSolver::mostPressureIterations has the step's most).
  std::vector<int> iters;
  /// Per face (empty beyond dim): sum_r theta_r,f u_f,r (theta upwinded) and the face pressure,
  /// from the pressure increment and the face pressure to the Lagrangian phase; the advection
  /// keeps the first two fluids' mass fluxes in them (advectFluids), so after a step they hold those.
  std::array<core::Field, 3> volFlux;
  std::array<core::Field, 3> pressFace;
  SolidFaces solidFaces;

  /// Allocates every field over `stored` (cells) and the faces of `owned`; dp only with the
  /// semi-implicit pressure, iters only with keepIterations.
  void allocate(const core::Box& owned, const core::Box& stored, int dim, bool semiImplicit, bool keepIterations);
};

}  // namespace mpmice::ice
