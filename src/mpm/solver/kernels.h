#pragma once
/// @brief The hot loops of an MPM step, templated on the shape function and the dimension.
///
/// Each kernel runs over a range of particles, evaluates the tensor-product stencil of its shape
/// (Shape::kNodes nodes per used direction) and scatters to or gathers from node fields through
/// raw pointers: no virtual calls, no allocations. Fields hold three components whatever the
/// dimension; only the first Dim are touched.
#include <cstddef>

#include "mpm/grid/grid.h"
#include "mpm/particles/particle_set.h"
#include "mpm/shape/shape_function.h"

namespace mpmice::mpm::kernels {

/// Calls f.template operator()<Shape, Dim>() for the run-time shape and dimension.
template <class F>
void dispatch(ShapeKind k, int dim, F&& f) {
  withShape(k, [&](auto s) {
    using S = decltype(s);
    if (dim == 1)
      f.template operator()<S, 1>();
    else if (dim == 2)
      f.template operator()<S, 2>();
    else
      f.template operator()<S, 3>();
  });
}

/// Stencil of one particle: first node and per-direction weights and physical gradients.
template <class Shape, int Dim>
struct Stencil {
  static constexpr int N = Shape::kNodes;
  static constexpr int NY = Dim >= 2 ? N : 1;
  static constexpr int NZ = Dim >= 3 ? N : 1;
  int base[3] = {0, 0, 0};
  double w[3][N] = {};
  double dw[3][N] = {};

  inline void compute(const ParticleSet& p, std::size_t i, const GridGeom& g) {
    for (int d = 0; d < Dim; ++d) {
      const double xi = (p.x[d][i] - g.origin[d]) * g.invDx[d];
      Shape::eval(xi, p.halfSize[d][i] * g.invDx[d], base[d], w[d], dw[d]);
      for (int a = 0; a < N; ++a) dw[d][a] *= g.invDx[d];
    }
    for (int d = Dim; d < 3; ++d) {
      base[d] = 0;
      w[d][0] = 1.0;
      dw[d][0] = 0.0;
    }
  }

  /// Calls f(node offset, weight, grad x, grad y, grad z) for every stencil node.
  template <class F>
  inline void forNodes(const GridGeom& g, F&& f) const {
    const std::int64_t o0 = g.index(base[0], base[1], base[2]);
    for (int c = 0; c < NZ; ++c)
      for (int b = 0; b < NY; ++b) {
        const double wyz = w[1][b] * w[2][c];
        const double dyz = dw[1][b] * w[2][c];
        const double wdz = w[1][b] * dw[2][c];
        const std::int64_t o = o0 + b * g.sy + c * g.sz;
        for (int a = 0; a < N; ++a)
          f(o + a, w[0][a] * wyz, dw[0][a] * wyz, w[0][a] * dyz, w[0][a] * wdz);
      }
  }
};

/// Mass and momentum to the nodes (lumped mass).
template <class Shape, int Dim>
void particlesToGrid(const ParticleSet& p, std::size_t begin, std::size_t end, const GridGeom& g,
                     double* mass, double* const mom[3]) {
  Stencil<Shape, Dim> s;
  for (std::size_t i = begin; i < end; ++i) {
    s.compute(p, i, g);
    const double m = p.mass[i];
    double mv[3] = {0, 0, 0};
    for (int d = 0; d < Dim; ++d) mv[d] = m * p.v[d][i];
    s.forNodes(g, [&](std::int64_t n, double w, double, double, double) {
      mass[n] += m * w;
      for (int d = 0; d < Dim; ++d) mom[d][n] += mv[d] * w;
    });
  }
}

/// Momentum only (MUSL's velocity remap).
template <class Shape, int Dim>
void momentumToGrid(const ParticleSet& p, std::size_t begin, std::size_t end, const GridGeom& g,
                    double* const mom[3]) {
  Stencil<Shape, Dim> s;
  for (std::size_t i = begin; i < end; ++i) {
    s.compute(p, i, g);
    double mv[3] = {0, 0, 0};
    for (int d = 0; d < Dim; ++d) mv[d] = p.mass[i] * p.v[d][i];
    s.forNodes(g, [&](std::int64_t n, double w, double, double, double) {
      for (int d = 0; d < Dim; ++d) mom[d][n] += mv[d] * w;
    });
  }
}

/// Internal force -V sigma grad(w) plus body force m g w and particle loads (fext + fsurf) w.
template <class Shape, int Dim>
void internalForces(const ParticleSet& p, std::size_t begin, std::size_t end, const GridGeom& g,
                    const double gravity[3], bool loads, double* const force[3]) {
  Stencil<Shape, Dim> s;
  for (std::size_t i = begin; i < end; ++i) {
    s.compute(p, i, g);
    const double V = p.vol[i];
    const double sxx = V * p.stress[kXX][i], syy = V * p.stress[kYY][i], szz = V * p.stress[kZZ][i];
    const double sxy = V * p.stress[kXY][i], syz = V * p.stress[kYZ][i], sxz = V * p.stress[kXZ][i];
    double b[3];
    for (int d = 0; d < Dim; ++d) b[d] = p.mass[i] * gravity[d] + (loads ? p.fext[d][i] + p.fsurf[d][i] : 0.0);
    s.forNodes(g, [&](std::int64_t n, double w, double gx, double gy, double gz) {
      force[0][n] += b[0] * w - (sxx * gx + sxy * gy + sxz * gz);
      if constexpr (Dim >= 2) force[1][n] += b[1] * w - (sxy * gx + syy * gy + syz * gz);
      if constexpr (Dim >= 3) force[2][n] += b[2] * w - (sxz * gx + syz * gy + szz * gz);
      (void)szz;
    });
  }
}

/// Grid to particles. kVelocity: FLIP/PIC velocity update from vL (and vn for the FLIP
/// increment); kMove: x += dt vL; kGradient: L = grad(vGrad).
template <class Shape, int Dim, bool kVelocity, bool kMove, bool kGradient>
void gridToParticles(ParticleSet& p, std::size_t begin, std::size_t end, const GridGeom& g,
                     const double* const vL[3], const double* const vn[3],
                     const double* const vGrad[3], double dt, double flip) {
  Stencil<Shape, Dim> s;
  for (std::size_t i = begin; i < end; ++i) {
    s.compute(p, i, g);
    double vnew[3] = {0, 0, 0}, vold[3] = {0, 0, 0}, L[3][3] = {};
    s.forNodes(g, [&](std::int64_t n, double w, double gx, double gy, double gz) {
      if constexpr (kVelocity || kMove)
        for (int d = 0; d < Dim; ++d) vnew[d] += w * vL[d][n];
      if constexpr (kVelocity)
        for (int d = 0; d < Dim; ++d) vold[d] += w * vn[d][n];
      if constexpr (kGradient) {
        const double gr[3] = {gx, gy, gz};
        for (int a = 0; a < Dim; ++a)
          for (int b = 0; b < Dim; ++b) L[a][b] += vGrad[a][n] * gr[b];
      }
    });
    for (int d = 0; d < Dim; ++d) {
      if constexpr (kMove) p.x[d][i] += dt * vnew[d];
      if constexpr (kVelocity)
        p.v[d][i] = flip * (p.v[d][i] + vnew[d] - vold[d]) + (1.0 - flip) * vnew[d];
    }
    if constexpr (kGradient)
      for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b) p.L[3 * a + b][i] = L[a][b];
  }
}

}  // namespace mpmice::mpm::kernels
