#pragma once
/// @brief The minimal fused MPM kernel bench_mpm_step measures beside the solver: what one core
/// reaches with two particle passes and one grid pass per step and nothing else.
///
/// PIC with the velocity gradient, compressible neo-Hookean (plane strain in 2D), structure of
/// arrays holding only what the method needs (x, v, F, mass, V0: 2 + 2 + 4 + 2 doubles per 2D
/// particle). One step:
///   P2G (one pass)  stencil, Kirchhoff stress tau = mu (F F^T - I) + lambda ln J I from F, then
///                   per node: mass m w, momentum m v w - dt V0 tau grad w (force folded in)
///   grid            v = p / m (0 on empty nodes), zero velocity on the outer node layers (walls)
///   G2P (one pass)  stencil, v = sum w v_i, L = sum v_i grad w^T, F = (I + dt L) F, x += dt v,
///                   max |v| for the next time step
/// dt = cfl h / (c + max |v|), c the P-wave speed at the reference density. Same problem as the
/// solver's benchmark (block, particles, material, initial velocity, CFL), so the two figures
/// compare the machinery, not the physics. Not the solver's method (USL, FLIP, Jaumann linear
/// elasticity, loads, boundary conditions, MPI): a lower bound on the cost of one step.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

namespace mpmice::mpm::bench {

template <class Shape, int Dim>
class FusedReference {
 public:
  static constexpr int N = Shape::kNodes;
  static constexpr int kPad = 2;  // node layers beyond the mesh (B-spline stencils)

  /// A block of `block`^Dim cells, `margin` empty cells round it, 2 particles per cell and
  /// direction; density rho, Young's modulus E, Poisson's ratio nu.
  FusedReference(int block, int margin, double rho, double E, double nu, double cfl)
      : cfl_(cfl), h_(1.0 / block), invH_(static_cast<double>(block)) {
    const int n = block + 2 * margin;
    for (int d = 0; d < 3; ++d) nodes_[d] = d < Dim ? n + 1 + 2 * kPad : 1;
    stride_[0] = 1;
    stride_[1] = nodes_[0];
    stride_[2] = nodes_[0] * nodes_[1];
    const std::size_t nn = static_cast<std::size_t>(nodes_[0]) * nodes_[1] * nodes_[2];
    gm_.assign(nn, 0.0);
    for (auto& c : gp_) c.assign(nn, 0.0);
    mu_ = E / (2 * (1 + nu));
    lambda_ = E * nu / ((1 + nu) * (1 - 2 * nu));
    c_ = std::sqrt((lambda_ + 2 * mu_) / rho);
    const int per = 2 * block;
    const double dp = h_ / 2, lo = margin * h_, vp = std::pow(dp, Dim);
    const double k = 2 * std::numbers::pi;
    const int nz = Dim == 3 ? per : 1;
    for (int kz = 0; kz < nz; ++kz)
      for (int ky = 0; ky < per; ++ky)
        for (int kx = 0; kx < per; ++kx) {
          const double p[3] = {lo + (kx + 0.5) * dp, lo + (ky + 0.5) * dp, lo + (kz + 0.5) * dp};
          for (int d = 0; d < Dim; ++d) {
            x_[d].push_back(p[d]);
            v_[d].push_back(0.05 * std::sin(k * p[d]) + 0.03 * std::cos(k * p[(d + 1) % Dim]));
          }
          for (int a = 0; a < Dim; ++a)
            for (int b = 0; b < Dim; ++b) F_[a * Dim + b].push_back(a == b ? 1.0 : 0.0);
          mass_.push_back(rho * vp);
          vol0_.push_back(vp);
        }
    for (std::size_t i = 0; i < mass_.size(); ++i) {
      double v2 = 0;
      for (int d = 0; d < Dim; ++d) v2 += v_[d][i] * v_[d][i];
      vmax_ = std::max(vmax_, std::sqrt(v2));
    }
  }

  [[nodiscard]] std::size_t size() const { return mass_.size(); }

  void step() {
    const double dt = cfl_ * h_ / (c_ + vmax_);
    for (auto* f : {&gm_, &gp_[0], &gp_[1], &gp_[2]}) std::fill(f->begin(), f->end(), 0.0);
    p2g(dt);
    grid();
    g2p(dt);
  }

 private:
  struct St {
    std::ptrdiff_t o;
    double w[Dim][N], g[Dim][N];
  };

  inline void stencil(std::size_t i, St& s) const {
    int base[3] = {0, 0, 0};
    for (int d = 0; d < Dim; ++d) {
      Shape::eval(x_[d][i] * invH_, 0.0, base[d], s.w[d], s.g[d]);
      for (int a = 0; a < N; ++a) s.g[d][a] *= invH_;
    }
    s.o = 0;
    for (int d = 0; d < Dim; ++d) s.o += static_cast<std::ptrdiff_t>(base[d] + kPad) * stride_[d];
  }

  /// Calls f(node, w, grad) over the stencil.
  template <class Fn>
  inline void nodes(const St& s, Fn&& f) const {
    if constexpr (Dim == 2) {
      for (int b = 0; b < N; ++b)
        for (int a = 0; a < N; ++a) {
          const double gr[2] = {s.g[0][a] * s.w[1][b], s.w[0][a] * s.g[1][b]};
          f(s.o + a + b * stride_[1], s.w[0][a] * s.w[1][b], gr);
        }
    } else {
      for (int c = 0; c < N; ++c)
        for (int b = 0; b < N; ++b) {
          const double wyz = s.w[1][b] * s.w[2][c];
          for (int a = 0; a < N; ++a) {
            const double gr[3] = {s.g[0][a] * wyz, s.w[0][a] * s.g[1][b] * s.w[2][c],
                                  s.w[0][a] * s.w[1][b] * s.g[2][c]};
            f(s.o + a + b * stride_[1] + c * stride_[2], s.w[0][a] * wyz, gr);
          }
        }
    }
  }

  void p2g(double dt) {
    double* gm = gm_.data();
    double* gp[3] = {gp_[0].data(), gp_[1].data(), gp_[2].data()};
    St s;
    for (std::size_t i = 0; i < size(); ++i) {
      stencil(i, s);
      double F[Dim][Dim], B[Dim][Dim];
      for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b) F[a][b] = F_[a * Dim + b][i];
      double J;
      if constexpr (Dim == 2)
        J = F[0][0] * F[1][1] - F[0][1] * F[1][0];
      else
        J = F[0][0] * (F[1][1] * F[2][2] - F[1][2] * F[2][1]) - F[0][1] * (F[1][0] * F[2][2] - F[1][2] * F[2][0]) +
            F[0][2] * (F[1][0] * F[2][1] - F[1][1] * F[2][0]);
      const double lnJ = std::log(J);
      // -dt V0 tau, tau = mu (F F^T - I) + lambda ln J I.
      const double k = -dt * vol0_[i];
      for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b) {
          double bb = 0;
          for (int c = 0; c < Dim; ++c) bb += F[a][c] * F[b][c];
          B[a][b] = k * (mu_ * (bb - (a == b ? 1.0 : 0.0)) + (a == b ? lambda_ * lnJ : 0.0));
        }
      const double m = mass_[i];
      double mv[Dim];
      for (int d = 0; d < Dim; ++d) mv[d] = m * v_[d][i];
      nodes(s, [&](std::ptrdiff_t n, double w, const double* gr) {
        gm[n] += m * w;
        for (int a = 0; a < Dim; ++a) {
          double f = 0;
          for (int b = 0; b < Dim; ++b) f += B[a][b] * gr[b];
          gp[a][n] += mv[a] * w + f;
        }
      });
    }
  }

  void grid() {
    const int lo = kPad, hi[3] = {nodes_[0] - 1 - kPad, nodes_[1] - 1 - kPad, nodes_[2] - 1 - kPad};
    for (int k = 0; k < nodes_[2]; ++k)
      for (int j = 0; j < nodes_[1]; ++j)
        for (int i = 0; i < nodes_[0]; ++i) {
          const std::size_t n = static_cast<std::size_t>(i + j * stride_[1] + k * stride_[2]);
          const bool wall = i <= lo || i >= hi[0] || (Dim >= 2 && (j <= lo || j >= hi[1])) ||
                            (Dim == 3 && (k <= lo || k >= hi[2]));
          const double inv = gm_[n] > 0 && !wall ? 1.0 / gm_[n] : 0.0;
          for (int d = 0; d < Dim; ++d) gp_[d][n] *= inv;
        }
  }

  void g2p(double dt) {
    const double* gv[3] = {gp_[0].data(), gp_[1].data(), gp_[2].data()};
    St s;
    double vmax2 = 0;
    for (std::size_t i = 0; i < size(); ++i) {
      stencil(i, s);
      double v[Dim] = {}, L[Dim][Dim] = {};
      nodes(s, [&](std::ptrdiff_t n, double w, const double* gr) {
        for (int a = 0; a < Dim; ++a) {
          const double vi = gv[a][n];
          v[a] += w * vi;
          for (int b = 0; b < Dim; ++b) L[a][b] += vi * gr[b];
        }
      });
      double F[Dim][Dim];
      for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b) F[a][b] = F_[a * Dim + b][i];
      for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b) {
          double f = F[a][b];
          for (int c = 0; c < Dim; ++c) f += dt * L[a][c] * F[c][b];
          F_[a * Dim + b][i] = f;
        }
      double v2 = 0;
      for (int d = 0; d < Dim; ++d) {
        v_[d][i] = v[d];
        x_[d][i] += dt * v[d];
        v2 += v[d] * v[d];
      }
      vmax2 = std::max(vmax2, v2);
    }
    vmax_ = std::sqrt(vmax2);
  }

  double cfl_, h_, invH_, mu_ = 0, lambda_ = 0, c_ = 0, vmax_ = 0;
  int nodes_[3] = {1, 1, 1};
  std::ptrdiff_t stride_[3] = {1, 1, 1};
  std::array<std::vector<double>, Dim> x_, v_;
  std::array<std::vector<double>, Dim * Dim> F_;
  std::vector<double> mass_, vol0_;
  std::vector<double> gm_;
  std::array<std::vector<double>, 3> gp_;
};

}  // namespace mpmice::mpm::bench
