#pragma once
/// @brief The small phase steps of ICE that need nothing but the state, the mesh and this rank's
/// owned cells: IceSolver's phases call them (see ice/solver/ice_solver.h for the order).
///
/// Face fields live on the faces normal to each direction d < dim of the owned box (face index i
/// = low face of cell i); cell fields over the stored box, read at the owned cells and their face
/// neighbours (their ghosts must be filled).
#include <array>
#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/mesh/mesh.h"
#include "ice/state/ice_state.h"

namespace mpmice::ice {

/// Mixture density rho, acoustic impedance z = rho c (Wood) and mass-averaged velocity u_d of
/// every cell of `box` (the owned cells and one layer around them, or a block of slabs of it:
/// forMixBlocks): what the Riemann face pressure and its rate in the stable step read, computed
/// once per cell (not per face side).
/// A cell holding an external material (a solid, mass > 0) gets z = 0: the Riemann terms act at
/// faces between fluid cells only (a solid's surface load stays ICE's average face pressure).
struct CellMixes {
  core::Box box;
  std::vector<double> rho, z, p;
  std::array<std::vector<double>, 3> u;
  /// Scale the Riemann terms by the faces' Mach number (lowMachScale in face_phase.cpp).
  bool lowMach = false;
  /// With lowMach: the cell pressures p is made from (stored-box indexed); null: the state's.
  const double* pressure = nullptr;
};
/// Fills x for the owned box grown by one layer (ghosts of mass, velocity, theta, specific
/// volume and kappa filled); reuses x's storage.
void computeCellMixes(const IceState& st, const core::Box& owned, int dim, CellMixes& x);
/// The same over `box` (inside the owned box grown by one): x.box = box.
void computeCellMixesOver(const IceState& st, const core::Box& box, int dim, CellMixes& x);
/// About how many cells the mixtures cover at a time (forMixBlocks).
inline constexpr std::int64_t kMixWindowCells = 32768;
/// The readers of the mixtures a block of slabs at a time (slabs: the cells or faces with one
/// index in the last direction, top = dim - 1; rows in 2D, planes in 3D), so that none keeps them
/// for the whole box: for each block lo .. hi of the slabs first .. last (in order), x is made
/// over the slabs lo - 1 .. hi + 1 of the owned box grown by one (those there are; a cell's
/// values are its own: the same as over the whole box), then f(lo, hi). A cell's faces and
/// neighbours in top lie within one slab of it. In 1D one block.
template <class F>
void forMixBlocks(const IceState& st, const core::Box& owned, int dim, CellMixes& x, int first, int last, F&& f) {
  const core::Box grown = owned.grow(1, dim);
  const int top = dim - 1;
  std::int64_t slab = 1;
  for (int q = 0; q < top; ++q) slab *= grown.length(q);
  const int n = dim == 1 ? last - first + 1 : static_cast<int>(std::max<std::int64_t>(1, kMixWindowCells / slab));
  for (int lo = first; lo <= last; lo += n) {
    const int hi = std::min(last, lo + n - 1);
    core::Box b = grown;
    b.lo[top] = std::max(grown.lo[top], lo - 1);
    b.hi[top] = std::min(grown.hi[top], hi + 1);
    computeCellMixesOver(st, b, dim, x);
    f(lo, hi);
  }
}
/// The strides of a mixtures' box along each direction (the same for every block of forMixBlocks:
/// the box's lengths below top are the grown box's).
inline std::array<std::int64_t, 3> cellMixStrides(const core::Box& owned, int dim) {
  const core::Box g = owned.grow(1, dim);
  return {1, g.length(0), std::int64_t(g.length(0)) * g.length(1)};
}

/// Face volume fluxes U_f = sum_r theta_r u_f,r (theta from the upwind cell; st.volFlux).
void computeVolumeFluxes(IceState& st, const core::Mesh& mesh, const core::Box& owned);
/// Their divergence div U at a cell: U[d] the volume fluxes normal to d, f[d] the cell's low face
/// in them, fs[d] the stride to its high face. Computed where it is read (the pressure increment,
/// the Lagrangian phase) rather than kept per cell: a few operations against a double per cell.
inline double volumeFluxDivergence(int dim, const double* const* U, const std::int64_t* f, const std::int64_t* fs,
                                   const double* dx) {
  double div = 0;
  for (int d = 0; d < dim; ++d) div += (U[d][f[d] + fs[d]] - U[d][f[d]]) / dx[d];
  return div;
}
/// The face volume fluxes as the cell loops read them, per direction of the mesh: the fluxes U
/// (st.volFlux), their face box (owned.faces(d): box[d].index(i, j, k) is cell (i, j, k)'s low
/// face), the stride from a cell's low face to its high one, and dx.
struct VolumeFluxFaces {
  const double* U[3] = {nullptr, nullptr, nullptr};
  core::Box box[3];
  std::int64_t stride[3] = {0, 0, 0};
  double dx[3] = {1, 1, 1};
  VolumeFluxFaces(const IceState& st, const core::Mesh& mesh, const core::Box& owned) {
    for (int d = 0; d < mesh.dim(); ++d) {
      U[d] = st.volFlux[d].data();
      box[d] = owned.faces(d);
      stride[d] = d == 0 ? 1 : (d == 1 ? box[d].length(0) : std::int64_t(box[d].length(0)) * box[d].length(1));
      dx[d] = mesh.dx(d);
    }
  }
  /// div U at the cell whose low faces are f[d].
  [[nodiscard]] double divergence(int dim, const std::int64_t* f) const {
    return volumeFluxDivergence(dim, U, f, stride, dx);
  }
};
/// Explicit pressure increment dp = -dt div U / kbar (0 where kbar = 0) added to the equilibrium
/// pressure st.press per owned cell (st.dp, where it is stored: the semi-implicit pressure).
void explicitPressureIncrement(IceState& st, const core::Mesh& mesh, const core::Box& owned, double dt);
/// Face pressure p_f = (p_L / rho_L + p_R / rho_R) / (1 / rho_L + 1 / rho_R) (rho: the cells'
/// mixture mass; the mean where both are empty; st.pressFace).
/// Face pressures (density-weighted), plus the shock viscosity q = rho_f (q1 c_f |du| + q2 du^2) at
/// faces in compression (du = u_R - u_L < 0 of the cells' mass-averaged velocities; rho_f the
/// harmonic mean of the mixture densities, c_f the smaller mixture sound speed); with riemann the
/// two-shock approximate Riemann dissipation -W_L W_R / (W_L + W_R) du at faces in compression,
/// W = rho (c + kShockImpedanceSlope |du|) of each cell (mixture density and Wood sound speed).
/// The two-shock Riemann dissipation's impedance W_L W_R / (W_L + W_R) at a face with velocity
/// jump du = u_R - u_L, W = z + kShockImpedanceSlope rho |du| of each side (z = rho c, the mixture's
/// acoustic impedance, rho its density); 0 in expansion (du >= 0) or where a side has no impedance.
[[nodiscard]] double riemannImpedance(double zL, double rhoL, double zR, double rhoR, double du, double scale = 1.0);
/// The Riemann dissipation's explicit rate on this rank: max over owned cells of
/// sum_d (Z_lo + Z_hi) / (rho dx_d), Z the riemannImpedance of the cell's two faces normal to d and
/// rho its mixture density (the term is a diffusion of velocity with nu = Z dx / rho at faces in
/// compression; forward Euler is stable for dt <= 1 / rate). `cell` gets the stored-box index of
/// the cell that sets it. Needs mass, velocity, theta, specific volume and kappa in the ghosts.
/// `mixes`: the storage of the mixtures (forMixBlocks) if the caller keeps it (else local); x.lowMach
/// as the caller sets it.
[[nodiscard]] double riemannDissipationRate(const IceState& st, const core::Mesh& mesh, const core::Box& owned,
                                            std::int64_t* cell, CellMixes* mixes = nullptr);
void computeFacePressures(IceState& st, const core::Box& owned, int dim, double q1 = 0, double q2 = 0,
                          bool riemann = false, CellMixes* mixes = nullptr);

}  // namespace mpmice::ice
