#pragma once
/// @brief IceSolver's scratch between steps, by name: what the semi-implicit pressure solve
/// (phase 5) and the advection (phase 12) keep so as not to allocate every step. Nothing in
/// here is state: each phase overwrites what it reads before reading it.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "core/field/field.h"
#include "ice/linear/hypre_struct_pcg.h"
#include "ice/linear/jacobi_cg.h"
#include "ice/linear/linear_operator.h"

namespace mpmice::ice {

/// Phase 5, semi-implicit: the face mobilities, the pressure-increment system and its solver.
struct SemiImplicitScratch {
  /// phi_r,f: the face velocity's response to a pressure gradient (-dt phi grad dp) per
  /// material, on the faces normal to each direction.
  std::vector<std::array<core::Field, 3>> mobility;
  /// centre = kbar = sum_r theta_r kappa_r per cell, coef = dt^2 beta_f / dx^2 per face.
  linear::FaceStencil stencil;
  core::Field rhs;  // -dt div U* per owned cell
  /// The mobilities were computed with this step's face velocities (computeFaceVelocities) and
  /// nothing has set the state since (IceSolver::state()).
  bool mobilityFresh = false;
  std::unique_ptr<linear::JacobiCg> cg;
  std::unique_ptr<linear::HypreStructPcg> hypre;  // pfmg_pcg, smg_pcg: grid and matrix kept
};

/// Phase 3: each fluid's held share (heldShare in face_phase.cpp) per cell of the owned box grown
/// by one, computed once per step for the faces on both sides of a cell (external materials: empty).
struct HeldShares {
  core::Box box;
  std::vector<std::vector<double>> share;
};

/// The quantities the advection carries (the order of the terms of its face fluxes).
namespace advected {
enum : int { kMass = 0, kMomX, kMomY, kMomZ, kEnergy, kVolume, kEint, kCount };
}

/// Phase 12: per material the mass flux through each face (the other fluxes are that times a
/// face value, computed again where they are applied). The fluids are advected one after the
/// other (their fluxes are independent once the mass fluxes are known), so the rest is shared
/// by them: m e being accumulated (the mass, m u, m (e + |u|^2 / 2) and m v in the state's own
/// fields), the Lagrangian values those overwrite, the donors' positivity scale, the isentrope fits. The
/// positivity blend's per-donor sums live for two slabs of cells only (rows in 2D, planes in
/// 3D: pass 2 sweeps them in order and a slab's sums are complete once the faces above it are
/// done), its factors only where they are below 1; so do the outflow scale (kept where it is not
/// 1) and the isentrope fits.
struct AdvectionScratch {
  struct Material {
    std::array<core::Field, 3> massFlux;    // one component per face normal to each direction
  };
  /// An owned donor whose outgoing face values are blended (factor b < 1).
  struct Blend {
    std::int64_t cell;
    double b;
  };
  std::vector<Material> mat;
  /// Per material, the stored cells whose outflow scale is not 1 and their scale, in increasing
  /// cell order (computed once per step for the fluid mass after advection, in the fluid's
  /// specific volume's array, then free: advection_phase.cpp, outflowScale).
  std::vector<std::vector<std::pair<std::int64_t, double>>> capped;
  /// The outflow scale of the fluid being advected over two slabs of stored cells (s - 1 and s,
  /// as the isentrope fits below), put back from `capped` as the flux passes reach slab s.
  std::vector<double> scaleWindow;
  /// Per stored cell, of the fluid being advected: m e (the fallback of the conversion; m u and
  /// m (e + |u|^2 / 2) are accumulated in its velocity and energy, advection_phase.cpp).
  std::vector<double> eint;
  /// The Lagrangian velocity (the mesh's dimension of components) and internal energy of the
  /// fluid being advected over a window of consecutive stored slabs, one array after the other:
  /// the face values' sources, copied as the flux passes reach them, before the slab's velocity
  /// and energy become its conserved amounts (advection_phase.cpp, lagWindow).
  std::vector<double> lagWindow;
  /// The Lagrangian values of the owned cells read after their slab has left the window, in
  /// increasing cell order once pass 2 is done: the positivity blend's donors and their face
  /// neighbours, the owned cells beside a ghost (a ghost donor's blend is known after pass 2),
  /// and the cells whose conversion drops them as a trace (they keep their Lagrangian values).
  struct LagCell {
    std::int64_t cell;
    double u[3];
    double e;
  };
  std::vector<LagCell> lagKept;
  /// The owned cells of the fluid being advected that its conversion drops as traces, in
  /// increasing order.
  std::vector<std::int64_t> dropCells;
  /// Over the owned cells of two consecutive slabs, kRemSums arrays one after the other (a row's
  /// cells consecutive in each, for the lanes): the donor's mass left after its outflows and the
  /// outflows' sums the positivity blend needs (advection_phase.cpp).
  std::vector<double> remainder;
  std::vector<Blend> blends;  // the blended donors of the fluid being advected
  /// Each donor's face-value blend (1: none), with ghosts, of the fluid being advected; allocated
  /// on the first step with a blend (most scenes have none).
  core::Field blend;
  /// The local stiffened-gas fit of the EOS at each stored cell's Lagrangian state of the fluid
  /// being advected (second order only): Gruneisen coefficient (NaN where the fit is not
  /// admissible) and pi, so that the cell's isentrope is e_s(v) = pi v + (e_c - pi v_c) (v_c / v)^Gamma.
  /// Over two slabs of stored cells (s - 1 and s, consecutive as in the stored box), made as the
  /// flux passes reach slab s (advection_phase.cpp, fitWindow).
  std::vector<double> isenGamma, isenPi;
  /// More than one fluid: the fluids' mass after advection over one row of owned cells, made as
  /// a fluid's conversion reaches the row (advection_phase.cpp, fluidMassRow), and per fluid the
  /// owned cells whose nonzero mass after advection its conversion dropped (a trace), in
  /// increasing cell order, for the conversions of the fluids after it.
  std::vector<double> fluidMassRow;
  std::vector<std::vector<std::pair<std::int64_t, double>>> dropped;
  /// The batch EOS arguments of the isentrope fits, kEosChunk cells at a time.
  static constexpr std::size_t kEosChunk = 512;
  std::vector<double> eosRho, eosE, eosP1, eosP2;
};

}  // namespace mpmice::ice
