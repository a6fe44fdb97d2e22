// NodeCellOperators::solidFaceTransport: the face fluxes of the node-to-cell average of a solid's
// mass (node_cell_operators.h). With a tensor-product shape w_i(x) = prod_d s_i,d(x_d) and the
// node-to-cell shares (1/2 per direction at an interior node, 1 at a domain face), a particle's
// share of cell c is prod_d g_c,d(x_d), g_c,d = sum over the cell's two nodes of share s. In d,
// g_c,d = H_lo(c) - H_hi(c) with H_f = (1/2) s_I + sum_{i > I} s_i for the face f at node I
// (the share above f), so d/dt of the cell's share is sum_d (H'_lo - H'_hi) v_d prod_{e != d} g_c,e:
// the difference of the face fluxes H'_f v_d prod g. Accumulated at the nodes of each particle's
// stencil, then combined into faces with the node-to-cell shares.
#include "mpm/cell/node_cell_operators.h"
#include "mpm/cell/open_face_images.h"
#include "mpm/solver/kernels.h"

namespace mpmice::mpm {

void NodeCellOperators::solidFaceTransport(int material, core::Field& density, core::Field& flux) {
  Grid& g = grid_;
  if (faceTransport_.npts() == 0)
    faceTransport_ = core::Field("face_transport", core::Centering::Node, g.box(), 6, Grid::kGhost);
  core::Field& ft = faceTransport_;
  ft.fill(0.0);
  const int dim = mesh_.dim();
  const auto cells = mesh_.cells();
  const auto [b, e] = p_.materialRange(material);
  const GridGeom geom = g.geom();
  // Per particle and direction d, at the node indices of its stencil (the range of its mass
  // deposit, so the ranks' ghost nodes hold every contribution): m H'_I(x_d) prod_{e != d} s_n(x_e)
  // at node (I, n) in component d, and m v_d times it in component 3 + d. The transverse node
  // weights become the face's cell-row shares after the sum over ranks (below), as node masses
  // become cell masses.
  kernels::dispatch(shape_, dim, [&]<class S, int D>() {
    constexpr int N = S::kNodes;
    kernels::Stencil<S, D> stencil;
    for (std::size_t q = b; q < e; ++q) {
      stencil.compute(p_, q, geom);
      const double m = p_.mass[q];
      const int none[3] = {0, 0, 0};
      auto accumulate = [&](const kernels::Stencil<S, D>& st, const int(&shift)[3]) {
      // Nodes inside the mesh in the shifted directions of an image (all nodes for the particle).
      auto inside = [&](int d, int idx) { return shift[d] == 0 || (idx >= 0 && idx <= cells[d]); };
      for (int d = 0; d < D; ++d) {
        double hp[N];
        double above = 0;
        for (int a = N - 1; a >= 0; --a) {
          hp[a] = 0.5 * st.dw[d][a] + above;
          above += st.dw[d][a];
        }
        const double mv = m * p_.v[d][q];
        const int e1 = (d + 1) % 3, e2 = (d + 2) % 3;
        const int n1 = e1 < D ? N : 1, n2 = e2 < D ? N : 1;
        for (int a = 0; a < N; ++a) {
          if (hp[a] == 0.0) continue;
          int idx[3] = {0, 0, 0};
          idx[d] = st.base[d] + a;
          if (!inside(d, idx[d])) continue;
          for (int b1 = 0; b1 < n1; ++b1) {
            const double w1 = e1 < D ? st.w[e1][b1] : 1.0;
            if (e1 < D) idx[e1] = st.base[e1] + b1;
            if (e1 < D && !inside(e1, idx[e1])) continue;
            for (int b2 = 0; b2 < n2; ++b2) {
              const double w2 = e2 < D ? st.w[e2][b2] : 1.0;
              if (e2 < D) idx[e2] = st.base[e2] + b2;
              if (e2 < D && !inside(e2, idx[e2])) continue;
              const double h = hp[a] * w1 * w2;
              ft(idx[0], idx[1], idx[2], d) += m * h;
              ft(idx[0], idx[1], idx[2], 3 + d) += mv * h;
            }
          }
        }
      }
      };
      accumulate(stencil, none);
      // Its zero-gradient images beyond open faces (open_face_images.h), with its velocity.
      forOpenFaceImages(mesh_, open_, p_, q, geom, stencil, accumulate);
    }
  });
  g.sumAndFill({&ft});
  // The low face of cell (i, j, k) in d: its node in d, and in each other direction the cell's
  // two nodes with the node-to-cell share (1/2 inside the mesh, 1 on its faces).
  const double V = mesh_.cellVolume();
  core::forEach(cells_, [&](int i, int j, int k) {
    for (int d = 0; d < 3; ++d) {
      density(i, j, k, d) = flux(i, j, k, d) = 0.0;
      if (d >= dim) continue;
      const int e1 = (d + 1) % 3, e2 = (d + 2) % 3;
      const int c[3] = {i, j, k};
      double sd = 0, sf = 0;
      for (int o1 = 0; o1 < (e1 < dim ? 2 : 1); ++o1)
        for (int o2 = 0; o2 < (e2 < dim ? 2 : 1); ++o2) {
          int n[3] = {i, j, k};
          double share = 1.0;
          if (e1 < dim) {
            n[e1] = c[e1] + o1;
            if ((n[e1] > 0 && n[e1] < cells[e1]) || open_.onFace(mesh_, e1, n[e1])) share *= 0.5;
          }
          if (e2 < dim) {
            n[e2] = c[e2] + o2;
            if ((n[e2] > 0 && n[e2] < cells[e2]) || open_.onFace(mesh_, e2, n[e2])) share *= 0.5;
          }
          sd += share * ft(n[0], n[1], n[2], d);
          sf += share * ft(n[0], n[1], n[2], 3 + d);
        }
      const double A = V / mesh_.dx(d);
      density(i, j, k, d) = sd / A;
      flux(i, j, k, d) = sf / A;
    }
  });
}

}  // namespace mpmice::mpm
