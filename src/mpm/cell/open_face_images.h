#pragma once
/// @brief Zero-gradient images of the particles at the open mesh faces (free, outflow) for the
/// node-to-cell average of MPM-ICE (node_cell_operators.h).
///
/// ICE fills its ghost cells beyond an open face with a copy of the boundary cell (zero gradient):
/// as far as ICE is concerned a solid reaching such a face continues beyond it. MPM's grid leaves
/// the face alone (the solid ends there), so the node-to-cell average, which gave a face node's
/// whole mass to its one row of cells (share 1, right at a mirror plane), read a solid moving along
/// the face normal as leaving a gap in one boundary row and overfilling the other: a plate moving
/// 1e-9 m along y between free y faces lost 4e-7 of its boundary row's mass, and ICE expanded
/// the steel to fill it (-3e4 Pa, then a rarefied trace of air that collapsed the time step). With
/// the images, the face nodes get what the continued solid would put on them and count as interior
/// nodes (share 1/2 in that direction), so a translation along the normal changes no cell.
///
/// The images of particle i: it copied by one and by two cells outward across each open face whose
/// boundary row of cells holds it (ICE's two ghost layers; every combination at an edge or
/// corner), with its own mass, velocity, volume and temperature; they act on the nodes inside the
/// mesh (index 0 .. n in the shifted directions) only.
#include <algorithm>
#include <array>

#include <cmath>
#include <cstdint>
#include <type_traits>

#include "mpm/cell/node_cell_operators.h"
#include "mpm/solver/kernels.h"

namespace mpmice::mpm {

/// Image layers beyond a face: ICE's ghost layers are all copies of the boundary cell, and the
/// widest stencils (GIMP, B-splines: up to 2 cells) reach the face nodes from the second one.
inline constexpr int kImageLayers = 2;

/// For each image of particle i: st holds the image's stencil, shift[d] its offset in cells (0,
/// +-1, +-2), and f(st, shift) is called (see forImageNodes for its nodes inside the mesh). The
/// particle's position is restored exactly.
template <class S, int D, class F>
void forOpenFaceImages(const core::Mesh& mesh, const OpenFaces& of, ParticleSet& p, std::size_t i,
                       const GridGeom& geom, kernels::Stencil<S, D>& st, F&& f) {
  if (!of.any) return;
  int opt[3][1 + 2 * kImageLayers] = {}, nopt[3] = {1, 1, 1}, total = 1;
  for (int d = 0; d < D; ++d) {
    if (!of.low[d] && !of.high[d]) continue;
    const int n = mesh.cells()[d];
    const int c = std::clamp(static_cast<int>(std::floor((p.x[d][i] - mesh.origin()[d]) / mesh.dx(d))), 0, n - 1);
    for (int l = 1; l <= kImageLayers; ++l) {
      if (of.low[d] && c == 0) opt[d][nopt[d]++] = -l;
      if (of.high[d] && c == n - 1) opt[d][nopt[d]++] = l;
    }
    total *= nopt[d];
  }
  if (total == 1) return;
  double x0[3] = {0, 0, 0};
  for (int d = 0; d < D; ++d) x0[d] = p.x[d][i];
  for (int combo = 1; combo < total; ++combo) {
    int shift[3] = {0, 0, 0}, r = combo;
    for (int d = 0; d < D; ++d) {
      shift[d] = opt[d][r % nopt[d]];
      r /= nopt[d];
    }
    for (int d = 0; d < D; ++d) p.x[d][i] = x0[d] + shift[d] * mesh.dx(d);
    st.compute(p, i, geom);
    for (int d = 0; d < D; ++d) p.x[d][i] = x0[d];
    f(st, shift);
  }
}

/// The nodes of an image stencil inside the mesh in its shifted directions: f(node offset, w) or,
/// with the gradients, f(node offset, w, grad x, grad y, grad z) (the products of forNodes).
template <class S, int D, class F>
void forImageNodes(const core::Mesh& mesh, const GridGeom& g, const kernels::Stencil<S, D>& st, const int (&shift)[3],
                   F&& f) {
  constexpr int N = S::kNodes;
  constexpr int NY = D >= 2 ? N : 1, NZ = D >= 3 ? N : 1;
  auto inside = [&](int d, int idx) { return shift[d] == 0 || (idx >= 0 && idx <= mesh.cells()[d]); };
  for (int c = 0; c < NZ; ++c) {
    const int k = st.base[2] + c;
    if (D >= 3 && !inside(2, k)) continue;
    const double wz = D >= 3 ? st.w[2][c] : 1.0, dz = D >= 3 ? st.dw[2][c] : 0.0;
    for (int b = 0; b < NY; ++b) {
      const int j = st.base[1] + b;
      if (D >= 2 && !inside(1, j)) continue;
      const double wy = D >= 2 ? st.w[1][b] : 1.0, dy = D >= 2 ? st.dw[1][b] : 0.0;
      const double wyz = wy * wz;
      for (int a = 0; a < N; ++a) {
        const int ii = st.base[0] + a;
        if (!inside(0, ii)) continue;
        const std::int64_t n = g.index(ii, D >= 2 ? j : 0, D >= 3 ? k : 0);
        if constexpr (std::is_invocable_v<F&, std::int64_t, double>)
          f(n, st.w[0][a] * wyz);
        else
          f(n, st.w[0][a] * wyz, st.dw[0][a] * wyz, st.w[0][a] * dy * wz, st.w[0][a] * wy * dz);
      }
    }
  }
}

}  // namespace mpmice::mpm
