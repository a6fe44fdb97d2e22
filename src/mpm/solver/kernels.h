#pragma once
/// @brief The hot loops of an MPM step, templated on the shape function and the dimension.
///
/// Each kernel runs over a range of particles, evaluates the tensor-product stencil of its shape
/// (Shape::kNodes nodes per used direction) and scatters to or gathers from node fields through
/// raw pointers: no virtual calls, no allocations. Fields hold three components whatever the
/// dimension; only the first Dim are touched.
#include <cstddef>
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <type_traits>

#ifdef __AVX__
#include <immintrin.h>
#endif

#include "mpm/grid/grid.h"
#include "mpm/particles/particle_set.h"
#include "mpm/shape/shape_function.h"

// The vector types below are passed and returned by value between inline functions of one
// translation unit; without AVX (MPMICE_SIMD baseline) GCC notes that a 32-byte vector's ABI
// differs from an AVX build's (-Wpsabi), which matters only for calls across objects built with
// different flags: none here.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace mpmice::mpm::kernels {

/// GCC vector types (vector extensions: AVX registers where the build has them, SSE2 pairs on the
/// baseline); lane-wise operations are the scalar ones.
using v2d = double __attribute__((vector_size(16)));
using v4d = double __attribute__((vector_size(32)));

/// Lane k of v in every lane (one permute with AVX2).
template <int k>
inline v4d splat(v4d v) {
  return __builtin_shufflevector(v, v, k, k, k, k);
}

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

/// The linear hat's cached stencil keeps its fraction f per direction (weights 1 - f and f,
/// gradients -1/dx and 1/dx: LinearShape::eval's operations); GIMP keeps weights and gradients.
template <class Shape>
inline constexpr bool kCompactRecord = std::is_same_v<Shape, LinearShape>;

/// The tensor-product loop over a stencil with first node o0 and per-direction weights w and
/// gradients dw: f(node offset, weight, grad x, grad y, grad z). In 1D and 2D the missing
/// directions (weight 1, gradient 0) are left out of the products: multiplying by an exact 1 and
/// adding exact zeros changes no bit, so every dimension gives the figures of the 3D formula.
template <int N, int Dim, class F>
inline void forStencilNodes(std::int64_t o0, const GridGeom& g, const double (&w)[3][N], const double (&dw)[3][N],
                            F&& f) {
  if constexpr (Dim == 1) {
    for (int a = 0; a < N; ++a) f(o0 + a, w[0][a], dw[0][a], 0.0, 0.0);
  } else if constexpr (Dim == 2) {
    for (int b = 0; b < N; ++b) {
      const double wy = w[1][b], dy = dw[1][b];
      const std::int64_t o = o0 + b * g.sy;
      for (int a = 0; a < N; ++a) f(o + a, w[0][a] * wy, dw[0][a] * wy, w[0][a] * dy, 0.0);
    }
  } else {
    for (int c = 0; c < N; ++c)
      for (int b = 0; b < N; ++b) {
        const double wyz = w[1][b] * w[2][c];
        const double dyz = dw[1][b] * w[2][c];
        const double wdz = w[1][b] * dw[2][c];
        const std::int64_t o = o0 + b * g.sy + c * g.sz;
        for (int a = 0; a < N; ++a) f(o + a, w[0][a] * wyz, dw[0][a] * wyz, w[0][a] * dyz, w[0][a] * wdz);
      }
  }
}

/// forStencilNodes with the node's weight and gradient as one vector (w, gx, gy, gz), for the
/// record kernels: f(node offset, wg). Each lane is the product forStencilNodes forms (lane k of
/// (w_a, dw_a, w_a, w_a) times lane k of the row's (wyz, wyz, dyz, wdz); the row's lanes are
/// forStencilNodes' wyz, dyz, wdz), so the same bits. 2D: the row is (wy, wy, dy, dy), lane 3 unused.
template <int N, int Dim, class F>
inline void forStencilNodesV(std::int64_t o0, const GridGeom& g, const double (&w)[3][N], const double (&dw)[3][N],
                             F&& f) {
  static_assert(Dim == 2 || Dim == 3);
  v4d ax[N];
  for (int a = 0; a < N; ++a) ax[a] = v4d{w[0][a], dw[0][a], w[0][a], w[0][a]};
  if constexpr (Dim == 2) {
    for (int b = 0; b < N; ++b) {
      const v4d row = {w[1][b], w[1][b], dw[1][b], dw[1][b]};  // lane 3 unused (gy again)
      const std::int64_t o = o0 + b * g.sy;
      for (int a = 0; a < N; ++a) f(o + a, ax[a] * row);
    }
  } else {
    for (int c = 0; c < N; ++c)
      for (int b = 0; b < N; ++b) {
        const v4d row = v4d{w[1][b], w[1][b], dw[1][b], w[1][b]} * v4d{w[2][c], w[2][c], w[2][c], dw[2][c]};
        const std::int64_t o = o0 + b * g.sy + c * g.sz;
        for (int a = 0; a < N; ++a) f(o + a, ax[a] * row);
      }
  }
}

#ifdef __AVX__
/// forStencilNodesV's loop from per-direction lane vectors (AVX builds): w[a] and dw[a] hold node
/// a's weight and gradient factor of direction d in lane d (lanes past Dim unused). The node
/// vectors are formed from the lanes by shuffles, the values forStencilNodesV forms from arrays
/// w[d][a], dw[d][a] (ax = (w_a, dw_a, w_a, w_a) of x; the rows (wy, wy, dy, dy) in 2D,
/// (wy, wy, dy, wy) * (wz, wz, wz, dz) in 3D): the same products, the same bits.
template <int N, int Dim, class F>
inline void forLaneNodesV(std::int64_t o0, const GridGeom& g, const v4d (&w)[N], const v4d (&dw)[N], F&& f) {
  static_assert(Dim == 2 || Dim == 3);
  v4d ax[N];
  for (int a = 0; a < N; ++a) ax[a] = __builtin_shufflevector(w[a], dw[a], 0, 4, 0, 0);
  if constexpr (Dim == 2) {
    for (int b = 0; b < N; ++b) {
      const v4d row = __builtin_shufflevector(w[b], dw[b], 1, 1, 5, 5);
      const std::int64_t o = o0 + b * g.sy;
      for (int a = 0; a < N; ++a) f(o + a, ax[a] * row);
    }
  } else {
    for (int c = 0; c < N; ++c) {
      const v4d zc = __builtin_shufflevector(w[c], dw[c], 2, 2, 2, 6);
      for (int b = 0; b < N; ++b) {
        const v4d row = __builtin_shufflevector(w[b], dw[b], 1, 1, 5, 1) * zc;
        const std::int64_t o = o0 + b * g.sy + c * g.sz;
        for (int a = 0; a < N; ++a) f(o + a, ax[a] * row);
      }
    }
  }
}

/// 1 / dx per direction as lanes (1 past Dim).
template <int Dim>
inline v4d invDxLanes(const GridGeom& g) {
  return v4d{g.invDx[0], g.invDx[1], Dim == 3 ? g.invDx[2] : 1.0, 1.0};
}

/// Particle i's grid coordinates (x - origin) * (1 / dx) as lanes, Stencil::compute's operations
/// (0 past Dim).
template <int Dim>
inline v4d gridCoordinateLanes(const ParticleSet& p, std::size_t i, const GridGeom& g) {
  const v4d x = {p.x[0][i], p.x[1][i], Dim == 3 ? p.x[2][i] : 0.0, 0.0};
  const v4d origin = {g.origin[0], g.origin[1], Dim == 3 ? g.origin[2] : 0.0, 0.0};
  return (x - origin) * invDxLanes<Dim>(g);
}

/// floorIndex of each lane as a double (a rounding instruction; + 0.0 makes a -0 floor the +0 of
/// floorIndex's int: the same value) and the offset of the node at those indices.
template <int Dim>
inline v4d floorLanes(v4d x, const GridGeom& g, std::int64_t& offset) {
  const v4d fl = v4d(_mm256_floor_pd(__m256d(x))) + 0.0;
  const __m128i b = _mm256_cvttpd_epi32(__m256d(fl));
  offset = g.index(_mm_extract_epi32(b, 0), _mm_extract_epi32(b, 1), Dim == 3 ? _mm_extract_epi32(b, 2) : 0);
  return fl;
}

/// Particle i's quadratic B-spline stencil evaluated with the directions as lanes: lane d takes
/// the operations of Stencil::compute and BSpline2Shape::eval for direction d; then
/// forLaneNodesV. Returns the first node's offset.
template <int Dim, class F>
inline std::int64_t bspline2NodesV(const ParticleSet& p, std::size_t i, const GridGeom& g, F&& f) {
  const v4d invDx = invDxLanes<Dim>(g);
  const v4d xi = gridCoordinateLanes<Dim>(p, i, g);
  std::int64_t o0;
  const v4d fl = floorLanes<Dim>(xi - 0.5, g, o0);
  const v4d r0 = xi - fl;
  const v4d r1 = r0 - 1.0;
  const v4d r2 = r0 - 2.0;
  const v4d t0 = 1.5 - r0, t2 = 1.5 + r2;
  const v4d w[3] = {0.5 * t0 * t0, 0.75 - r1 * r1, 0.5 * t2 * t2};
  const v4d dw[3] = {-t0 * invDx, (-2.0 * r1) * invDx, t2 * invDx};
  forLaneNodesV<3, Dim>(o0, g, w, dw, f);
  return o0;
}
#endif

/// Stencil of one particle: first node and per-direction weights and physical gradients.
template <class Shape, int Dim>
struct Stencil {
  static constexpr int N = Shape::kNodes;
  static constexpr int NY = Dim >= 2 ? N : 1;
  static constexpr int NZ = Dim >= 3 ? N : 1;
  // Set by compute() (what forNodes and store read); not zero-filled first, as a local per particle.
  int base[3];
  double w[3][N];
  double dw[3][N];

  inline void compute(const ParticleSet& p, std::size_t i, const GridGeom& g) {
    for (int d = 0; d < Dim; ++d) {
      const double xi = (p.x[d][i] - g.origin[d]) * g.invDx[d];  // grid coordinate
      Shape::eval(xi, p.halfSize[d][i] * g.invDx[d], base[d], w[d], dw[d]);
      for (int a = 0; a < N; ++a) dw[d][a] *= g.invDx[d];
    }
    for (int d = Dim; d < 3; ++d) {
      base[d] = 0;
      w[d][0] = 1.0;
      dw[d][0] = 0.0;
    }
  }

  /// Calls f(node offset, weight, grad x, grad y, grad z) for every stencil node; returns the
  /// offset of the first node.
  template <class F>
  inline std::int64_t forNodes(const GridGeom& g, F&& f) const {
    const std::int64_t o0 = g.index(base[0], base[1], base[2]);
    forStencilNodes<N, Dim>(o0, g, w, dw, f);
    return o0;
  }
  /// forNodes with f(node offset, (w, gx, gy, gz)) (forStencilNodesV; 2D and 3D).
  template <class F>
  inline std::int64_t forNodesV(const GridGeom& g, F&& f) const {
    const std::int64_t o0 = g.index(base[0], base[1], base[2]);
    forStencilNodesV<N, Dim>(o0, g, w, dw, f);
    return o0;
  }

  /// Stores this stencil in a cache record (StencilCache layout).
  inline void store(std::int64_t& offset, double* rec, const GridGeom& g) const {
    offset = g.index(base[0], base[1], base[2]);
    if constexpr (kCompactRecord<Shape>) {
      for (int d = 0; d < Dim; ++d) rec[d] = w[d][1];
    } else {
      for (int d = 0; d < Dim; ++d)
        for (int a = 0; a < N; ++a) {
          rec[d * N + a] = w[d][a];
          rec[(Dim + d) * N + a] = dw[d][a];
        }
    }
  }
};

/// The stencils of every particle for one step: computed once, in the particle-to-grid pass, and
/// reused by the force pass and the grid-to-particle passes (positions change only in the last
/// one). Per particle: the flat offset of its first node and one record of Dim x N weights then
/// Dim x N physical gradients (per direction: the tensor product is formed on use, with the same
/// products as Stencil::forNodes, so the results are bit-for-bit those of recomputing).
/// kCompactRecord shapes keep one fraction per direction and recompute weights and gradients.
template <class Shape, int Dim>
struct StencilCache {
  static constexpr int N = Shape::kNodes;
  static constexpr int kRecord = kCompactRecord<Shape> ? Dim : 2 * Dim * N;
  std::int64_t* offset;
  double* rec;

  /// Particle i's weights and gradients per direction.
  inline void weights(std::size_t i, const GridGeom& g, double (&w)[3][N], double (&dw)[3][N]) const {
    const double* r = rec + i * kRecord;
    if constexpr (kCompactRecord<Shape>) {
      for (int d = 0; d < Dim; ++d) {
        w[d][0] = 1.0 - r[d];
        w[d][1] = r[d];
        dw[d][0] = -1.0 * g.invDx[d];
        dw[d][1] = 1.0 * g.invDx[d];
      }
    } else {
      for (int d = 0; d < Dim; ++d)
        for (int a = 0; a < N; ++a) {
          w[d][a] = r[d * N + a];
          dw[d][a] = r[(Dim + d) * N + a];
        }
    }
  }
  /// Calls f(node offset, weight, grad x, grad y, grad z) for every node of particle i's stencil;
  /// returns the offset of its first node.
  template <class F>
  inline std::int64_t forNodes(std::size_t i, const GridGeom& g, F&& f) const {
    double w[3][N], dw[3][N];
    weights(i, g, w, dw);
    forStencilNodes<N, Dim>(offset[i], g, w, dw, f);
    return offset[i];
  }
  /// forNodes with f(node offset, (w, gx, gy, gz)) (forStencilNodesV; 2D and 3D). The linear
  /// hat's record with AVX as lanes: weights()'s operations lane by lane, then forLaneNodesV.
  template <class F>
  inline std::int64_t forNodesV(std::size_t i, const GridGeom& g, F&& f) const {
#ifdef __AVX__
    if constexpr (std::is_same_v<Shape, LinearShape>) {
      const double* r = rec + i * kRecord;
      const v4d invDx = invDxLanes<Dim>(g);
      const v4d fr = {r[0], r[1], Dim == 3 ? r[2] : 0.0, 0.0};
      const v4d w[2] = {1.0 - fr, fr};
      const v4d dw[2] = {-1.0 * invDx, 1.0 * invDx};
      forLaneNodesV<2, Dim>(offset[i], g, w, dw, f);
      return offset[i];
    }
#endif
    double w[3][N], dw[3][N];
    weights(i, g, w, dw);
    forStencilNodesV<N, Dim>(offset[i], g, w, dw, f);
    return offset[i];
  }
};

/// Stencil sources of the kernels: forNodes(i, g, f) over particle i's stencil.
/// Evaluated on use (the B-splines' step passes, the MPM-ICE operators' extra passes). Where the
/// stencil lives is chosen by instruction count (callgrind, 3 steps of the 2D bench block): here a
/// member (2D bspline2 USL 1.071e9; as a local of forNodes 1.119e9), in StoredStencils a local
/// (2D linear 6.53e8; as a member 6.73e8: the node stores of f no longer force its reloads).
template <class Shape, int Dim>
struct EvaluatedStencils {
  static constexpr int N = Shape::kNodes;
  const ParticleSet& p;
  mutable Stencil<Shape, Dim> s;
  template <class F>
  inline std::int64_t forNodes(std::size_t i, const GridGeom& g, F&& f) const {
    s.compute(p, i, g);
    return s.forNodes(g, f);
  }
  /// The vector form evaluates into a local stencil (its values stay in registers); the quadratic
  /// B-spline with AVX in vector lanes over the directions (bspline2NodesV).
  template <class F>
  inline std::int64_t forNodesV(std::size_t i, const GridGeom& g, F&& f) const {
#ifdef __AVX__
    if constexpr (std::is_same_v<Shape, BSpline2Shape>) return bspline2NodesV<Dim>(p, i, g, f);
#endif
    Stencil<Shape, Dim> st;
    st.compute(p, i, g);
    return st.forNodesV(g, f);
  }
};
/// Evaluated and stored in a StencilCache for the passes after it (the step's particle-to-grid).
template <class Shape, int Dim>
struct StoredStencils {
  static constexpr int N = Shape::kNodes;
  const ParticleSet& p;
  StencilCache<Shape, Dim> cache;
  template <class F>
  inline std::int64_t forNodes(std::size_t i, const GridGeom& g, F&& f) const {
    Stencil<Shape, Dim> s;
    s.compute(p, i, g);
    s.store(cache.offset[i], cache.rec + i * StencilCache<Shape, Dim>::kRecord, g);
    return s.forNodes(g, f);
  }
  /// The linear hat with AVX as lanes: Stencil::compute, LinearShape::eval and Stencil::store
  /// lane by lane (the record is the fraction f per direction), then forLaneNodesV.
  template <class F>
  inline std::int64_t forNodesV(std::size_t i, const GridGeom& g, F&& f) const {
#ifdef __AVX__
    if constexpr (std::is_same_v<Shape, LinearShape>) {
      const v4d invDx = invDxLanes<Dim>(g);
      const v4d xi = gridCoordinateLanes<Dim>(p, i, g);
      std::int64_t o0;
      const v4d fr = xi - floorLanes<Dim>(xi, g, o0);
      cache.offset[i] = o0;
      double* r = cache.rec + i * StencilCache<Shape, Dim>::kRecord;
      for (int d = 0; d < Dim; ++d) r[d] = fr[d];
      const v4d w[2] = {1.0 - fr, fr};
      const v4d dw[2] = {-1.0 * invDx, 1.0 * invDx};
      forLaneNodesV<2, Dim>(o0, g, w, dw, f);
      return o0;
    }
#endif
    Stencil<Shape, Dim> s;
    s.compute(p, i, g);
    s.store(cache.offset[i], cache.rec + i * StencilCache<Shape, Dim>::kRecord, g);
    return s.forNodesV(g, f);
  }
};

/// Whether the step keeps the stencils of Shape (StencilCache) or evaluates them in each pass.
/// The B-splines are evaluated again: from the position, by the same function, so bit for bit what
/// a cache gives, for 0.7 % more instructions than a cache of the grid coordinate in a 2D
/// bspline2 USL step (callgrind, docs/mpm.md) and 24 B less per 2D particle (offset + record).
/// The linear hat and GIMP are kept (the hat's record is its fraction: 5.6 % fewer instructions).
template <class Shape>
inline constexpr bool kCacheStencils = !std::is_same_v<Shape, BSpline2Shape> && !std::is_same_v<Shape, BSpline3Shape>;

/// The stencil source of the passes after the step's particle-to-grid.
template <class Shape, int Dim>
using StepStencils = std::conditional_t<kCacheStencils<Shape>, StencilCache<Shape, Dim>, EvaluatedStencils<Shape, Dim>>;

/// The energy ledger's particle sums, kinetic energy 1/2 m |v|^2 and stored work, accumulated in
/// particle order by a pass that reads the particles anyway (the same expressions and order as
/// MpmSolver::particleKinetic / particleWork: the same bits, without a pass of their own).
struct ParticleSums {
  double kinetic = 0, work = 0;
  static inline double kineticOf(const ParticleSet& p, std::size_t i) {
    return 0.5 * p.mass[i] * (p.v[0][i] * p.v[0][i] + p.v[1][i] * p.v[1][i] + p.v[2][i] * p.v[2][i]);
  }
  /// The terms of particles [begin, end), added in order.
  inline void add(const ParticleSet& p, std::size_t begin, std::size_t end) {
    double ke = kinetic, wk = work;
    for (std::size_t i = begin; i < end; ++i) {
      ke += kineticOf(p, i);
      wk += p.work[i];
    }
    kinetic = ke;
    work = wk;
  }
};

/// Mass and momentum to the nodes (lumped mass).
/// `sums` (when given): the particles' ledger sums over the range, taken in the same pass.
template <int Dim, class Src>
void particlesToGrid(const Src& src, const ParticleSet& p, std::size_t begin, std::size_t end, const GridGeom& g,
                     double* mass, double* const mom[3], ParticleSums* sums = nullptr) {
  double ke = sums ? sums->kinetic : 0.0, wk = sums ? sums->work : 0.0;  // kept in registers
  for (std::size_t i = begin; i < end; ++i) {
    if (sums) {
      ke += ParticleSums::kineticOf(p, i);
      wk += p.work[i];
    }
    const double m = p.mass[i];
    double mv[3] = {0, 0, 0};
    for (int d = 0; d < Dim; ++d) mv[d] = m * p.v[d][i];
    src.forNodes(i, g, [&](std::int64_t n, double w, double, double, double) {
      mass[n] += m * w;
      for (int d = 0; d < Dim; ++d) mom[d][n] += mv[d] * w;
    });
  }
  if (sums) {
    sums->kinetic = ke;
    sums->work = wk;
  }
}
template <class Shape, int Dim>
void particlesToGrid(const ParticleSet& p, std::size_t begin, std::size_t end, const GridGeom& g,
                     double* mass, double* const mom[3]) {
  particlesToGrid<Dim>(EvaluatedStencils<Shape, Dim>{p, {}}, p, begin, end, g, mass, mom);
}

/// Momentum only (MUSL's velocity remap).
template <int Dim, class Src>
void momentumToGrid(const Src& src, const ParticleSet& p, std::size_t begin, std::size_t end, const GridGeom& g,
                    double* const mom[3]) {
  for (std::size_t i = begin; i < end; ++i) {
    double mv[3] = {0, 0, 0};
    for (int d = 0; d < Dim; ++d) mv[d] = p.mass[i] * p.v[d][i];
    src.forNodes(i, g, [&](std::int64_t n, double w, double, double, double) {
      for (int d = 0; d < Dim; ++d) mom[d][n] += mv[d] * w;
    });
  }
}

/// One particle's force on its stencil nodes: internal force -V sigma grad(w) plus body force
/// m g w and particle loads (fext + fsurf) w. In 1D and 2D the terms with the gradient 0 of a
/// missing direction are left out (exact zeros).
template <int Dim>
struct ParticleForce {
  double b[3] = {0, 0, 0};
  double s[6] = {0, 0, 0, 0, 0, 0};  // V sigma
  ParticleForce(const ParticleSet& p, std::size_t i, const double gravity[3], bool loads) {
    const double V = p.vol[i];
    if (loads) {
      // A load column not stored (no scene loads, no surface forces) holds zeros.
      const bool ext = p.stored(p.fext[0]), surf = p.stored(p.fsurf[0]);
      for (int d = 0; d < Dim; ++d)
        b[d] = p.mass[i] * gravity[d] + ((ext ? p.fext[d][i] : 0.0) + (surf ? p.fsurf[d][i] : 0.0));
    } else {
      for (int d = 0; d < Dim; ++d) b[d] = p.mass[i] * gravity[d] + 0.0;
    }
    s[kXX] = V * p.stress[kXX][i];
    if constexpr (Dim >= 2) {
      s[kYY] = V * p.stress[kYY][i];
      s[kXY] = V * p.stress[kXY][i];
    }
    if constexpr (Dim == 3) {
      s[kZZ] = V * p.stress[kZZ][i];
      s[kYZ] = V * p.stress[kYZ][i];
      s[kXZ] = V * p.stress[kXZ][i];
    }
  }
  inline void scatter(double* const force[3], std::int64_t n, double w, double gx, double gy, double gz) const {
    if constexpr (Dim == 1) {
      force[0][n] += b[0] * w - s[kXX] * gx;
    } else if constexpr (Dim == 2) {
      force[0][n] += b[0] * w - (s[kXX] * gx + s[kXY] * gy);
      force[1][n] += b[1] * w - (s[kXY] * gx + s[kYY] * gy);
    } else {
      force[0][n] += b[0] * w - (s[kXX] * gx + s[kXY] * gy + s[kXZ] * gz);
      force[1][n] += b[1] * w - (s[kXY] * gx + s[kYY] * gy + s[kYZ] * gz);
      force[2][n] += b[2] * w - (s[kXZ] * gx + s[kYZ] * gy + s[kZZ] * gz);
    }
  }
};

/// Internal, body and load forces to the nodes (ParticleForce).
template <int Dim, class Src>
void internalForces(const Src& src, const ParticleSet& p, std::size_t begin, std::size_t end, const GridGeom& g,
                    const double gravity[3], bool loads, double* const force[3]) {
  for (std::size_t i = begin; i < end; ++i) {
    const ParticleForce<Dim> pf(p, i, gravity, loads);
    src.forNodes(i, g, [&](std::int64_t n, double w, double gx, double gy, double gz) {
      pf.scatter(force, n, w, gx, gy, gz);
    });
  }
}

/// Particle-to-grid and internal forces in one pass (USL / MUSL, where the stress of the forces is
/// the one the particles carry into the step): mass, momentum and force of a particle are scattered
/// from one stencil evaluation, with the operations of particlesToGrid and internalForces in the
/// same particle order, so every node sum is bit for bit that of the two separate passes.
template <int Dim, class Src>
void particlesToGridWithForces(const Src& src, const ParticleSet& p, std::size_t begin, std::size_t end,
                               const GridGeom& g, double* mass, double* const mom[3], const double gravity[3],
                               bool loads, double* const force[3], ParticleSums* sums = nullptr) {
  double ke = sums ? sums->kinetic : 0.0, wk = sums ? sums->work : 0.0;  // kept in registers
  for (std::size_t i = begin; i < end; ++i) {
    if (sums) {
      ke += ParticleSums::kineticOf(p, i);
      wk += p.work[i];
    }
    const double m = p.mass[i];
    double mv[3] = {0, 0, 0};
    for (int d = 0; d < Dim; ++d) mv[d] = m * p.v[d][i];
    const ParticleForce<Dim> pf(p, i, gravity, loads);
    src.forNodes(i, g, [&](std::int64_t n, double w, double gx, double gy, double gz) {
      mass[n] += m * w;
      for (int d = 0; d < Dim; ++d) mom[d][n] += mv[d] * w;
      pf.scatter(force, n, w, gx, gy, gz);
    });
  }
  if (sums) {
    sums->kinetic = ke;
    sums->work = wk;
  }
}

/// The end of a particle's gather (gridToParticles, gridToRecords): x += dt vnew, the FLIP/PIC
/// velocity from vnew and vold, L = lOf(a, b). vnew / vold: arrays or vectors over the directions.
template <int Dim, bool kVelocity, bool kMove, bool kGradient, class Vec, class LOf>
inline void writeBackParticle(ParticleSet& p, std::size_t i, const Vec& vnew, const Vec& vold, double dt, double flip,
                              LOf lOf) {
  for (int d = 0; d < Dim; ++d) {
    if constexpr (kMove) p.x[d][i] += dt * vnew[d];
    if constexpr (kVelocity) p.v[d][i] = flip * (p.v[d][i] + vnew[d] - vold[d]) + (1.0 - flip) * vnew[d];
  }
  if constexpr (kGradient)
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) p.L[3 * a + b][i] = lOf(a, b);
}

/// Grid to particles. kVelocity: FLIP/PIC velocity update from vL (and vn for the FLIP
/// increment); kMove: x += dt vL; kGradient: L = grad(vGrad).
template <int Dim, bool kVelocity, bool kMove, bool kGradient, class Src>
void gridToParticles(const Src& src, ParticleSet& p, std::size_t begin, std::size_t end, const GridGeom& g,
                     const double* const vL[3], const double* const vn[3], const double* const vGrad[3], double dt,
                     double flip) {
  for (std::size_t i = begin; i < end; ++i) {
    double vnew[3] = {0, 0, 0}, vold[3] = {0, 0, 0}, L[3][3] = {};
    src.forNodes(i, g, [&](std::int64_t n, double w, double gx, double gy, double gz) {
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
    writeBackParticle<Dim, kVelocity, kMove, kGradient>(p, i, vnew, vold, dt, flip,
                                                        [&](int a, int b) { return L[a][b]; });
  }
}

// ---- Node records: the 2D / 3D scatter and gather on interleaved node data ---------------------
//
// The grid keeps each node field as its own array (core::Field), so a scalar scatter reads and
// writes five arrays per 2D node (mass, momentum, force) and seven per 3D node, one double each.
// The record kernels below keep a node's sums side by side in one 64-byte record instead and
// update them with vector operations (GCC vector extensions: AVX2 registers where the build has
// them, SSE2 pairs on the baseline): the lanes are the node fields, so each lane gets the very
// operation of the scalar kernel (the same products, sums and particle order) and the results
// keep their bits. No multiply-add is contracted (MPMICE_SIMD builds with -mno-fma).
// The records are unpacked into the grid's fields after the pass (unpackScatter); the gather reads
// records packed from the fields before it (packGather). Both cover only the nodes the particles'
// stencils reach (NodeRange), so the records' memory is touched where the particles are.

/// Doubles per node record (64 bytes).
inline constexpr int kRecordDoubles = 8;

template <class V>
inline V loadVec(const double* a) {
  V v;
  std::memcpy(&v, a, sizeof(V));
  return v;
}
template <class V>
inline void storeVec(double* a, const V& v) {
  std::memcpy(a, &v, sizeof(V));
}

/// The node offsets the particles' stencils reach: [lo, hi) (empty when lo >= hi).
struct NodeRange {
  std::int64_t lo = 0, hi = 0;
};

/// Offset of a stencil's last node from its first.
template <int N, int Dim>
inline std::int64_t stencilExtent(const GridGeom& g) {
  return (N - 1) + (Dim >= 2 ? (N - 1) * g.sy : 0) + (Dim == 3 ? (N - 1) * g.sz : 0);
}

/// One particle's contributions as vectors over the node fields of a scatter record
/// [mass, p_x, p_y, p_z | f_x, f_y, f_z, 0] (2D: the z lanes are 0 and stay 0):
///   record[0:4] += (m, m v_x, m v_y, m v_z) w
///   record[4:8] += b w - ((c_x gx + c_y gy) + c_z gz),  c_k = (V sigma_xk, V sigma_yk, V sigma_zk, 0)
/// lane by lane the expressions of particlesToGrid and ParticleForce::scatter.
template <int Dim, bool kForces>
struct RecordScatter {
  v4d mv{};       // (m, m v_x, m v_y, m v_z)
  v4d b{};        // (b_x, b_y, b_z, 0)
  v4d c[3] = {};  // columns of V sigma (Dim of them)
  RecordScatter(const ParticleSet& p, std::size_t i, const double gravity[3], bool loads) {
    const double m = p.mass[i];
    mv[0] = m;
    for (int d = 0; d < Dim; ++d) mv[1 + d] = m * p.v[d][i];
    if constexpr (kForces) {
      const ParticleForce<Dim> pf(p, i, gravity, loads);
      for (int d = 0; d < Dim; ++d) b[d] = pf.b[d];
      // c[k][a] = (V sigma)_{ak}: the symmetric stress's column k.
      c[0][0] = pf.s[kXX];
      c[0][1] = pf.s[kXY];
      c[1][0] = pf.s[kXY];
      c[1][1] = pf.s[kYY];
      if constexpr (Dim == 3) {
        c[0][2] = pf.s[kXZ];
        c[1][2] = pf.s[kYZ];
        c[2][0] = pf.s[kXZ];
        c[2][1] = pf.s[kYZ];
        c[2][2] = pf.s[kZZ];
      }
    }
  }
  /// Node n's record += this particle's terms; wg = (w, gx, gy, gz) (forStencilNodesV).
  inline void operator()(double* rec, std::int64_t n, v4d wg) const {
    double* r = rec + kRecordDoubles * n;
    const v4d wv = splat<0>(wg);
    storeVec(r, loadVec<v4d>(r) + mv * wv);
    if constexpr (kForces) {
      const v4d gxv = splat<1>(wg), gyv = splat<2>(wg);
      if constexpr (Dim == 2) {
        // Two lanes: the 2D force has no z component.
        const auto lo = [](v4d v) { return __builtin_shufflevector(v, v, 0, 1); };
        storeVec(r + 4, loadVec<v2d>(r + 4) + (lo(b) * lo(wv) - (lo(c[0]) * lo(gxv) + lo(c[1]) * lo(gyv))));
      } else {
        const v4d gzv = splat<3>(wg);
        storeVec(r + 4, loadVec<v4d>(r + 4) + (b * wv - ((c[0] * gxv + c[1] * gyv) + c[2] * gzv)));
      }
    }
  }
};

/// particlesToGrid (kForces false) or particlesToGridWithForces (true) into scatter records
/// (RecordScatter) for 2D and 3D; returns the range of nodes reached (unpackScatter's).
template <int Dim, bool kForces, class Src>
NodeRange scatterToRecords(const Src& src, const ParticleSet& p, std::size_t begin, std::size_t end,
                           const GridGeom& g, double* rec, const double gravity[3], bool loads,
                           ParticleSums* sums = nullptr) {
  static_assert(Dim == 2 || Dim == 3);
  double ke = sums ? sums->kinetic : 0.0, wk = sums ? sums->work : 0.0;  // kept in registers
  std::int64_t lo = INT64_MAX, hi = INT64_MIN;
  for (std::size_t i = begin; i < end; ++i) {
    if (sums) {
      ke += ParticleSums::kineticOf(p, i);
      wk += p.work[i];
    }
    const RecordScatter<Dim, kForces> rs(p, i, gravity, loads);
    const std::int64_t o0 = src.forNodesV(i, g, [&](std::int64_t n, v4d wg) { rs(rec, n, wg); });
    lo = std::min(lo, o0);
    hi = std::max(hi, o0);
  }
  if (sums) {
    sums->kinetic = ke;
    sums->work = wk;
  }
  if (begin >= end) return {};
  return {lo, hi + stencilExtent<Src::N, Dim>(g) + 1};
}

/// Adds the scatter records of `range` to the node fields (mass, momentum and, kForces, force) and
/// zeroes them for the next scatter. The fields are zero before (beginStep, projectToGrid), so each
/// node gets the record's sum, the scalar kernel's bits.
template <int Dim, bool kForces>
void unpackScatter(double* rec, NodeRange range, double* mass, double* const mom[3], double* const force[3]) {
  for (std::int64_t n = range.lo; n < range.hi; ++n) {
    double* r = rec + kRecordDoubles * n;
    mass[n] += r[0];
    for (int d = 0; d < Dim; ++d) mom[d][n] += r[1 + d];
    if constexpr (kForces)
      for (int d = 0; d < Dim; ++d) force[d][n] += r[4 + d];
    storeVec(r, v4d{});
    storeVec(r + 4, v4d{});
  }
}

/// Gather records: per node up to three slots of Dim values (2D: 2 doubles a slot; 3D: 4, the
/// last 0), in this order: the velocity of the update and move (kVelocity or kMove), the old
/// velocity of the FLIP increment (kVelocity) and the velocity of the gradient (kGradient, unless
/// kGradFromFirst: the first slot's). Packed over `range` by packGather, read by gridToRecords.
template <int Dim>
inline constexpr int kSlotDoubles = Dim == 2 ? 2 : 4;
template <int Dim, bool kVelocity, bool kMove, bool kGradient, bool kGradFromFirst>
struct GatherSlots {
  static constexpr bool kFirst = kVelocity || kMove;
  static constexpr int kOld = kFirst ? 1 : 0;
  static constexpr int kGrad = kGradFromFirst ? 0 : kOld + (kVelocity ? 1 : 0);
  static constexpr int kSlots = (kFirst ? 1 : 0) + (kVelocity ? 1 : 0) + (kGradient && !kGradFromFirst ? 1 : 0);
  static constexpr int kStride = kSlots * kSlotDoubles<Dim>;
  /// Whether the slots fit a record (not in 3D with three slots: the scalar kernel then).
  static constexpr bool kFits = kStride <= kRecordDoubles;
  static_assert(!kGradFromFirst || kFirst);
};

template <int Dim, bool kVelocity, bool kMove, bool kGradient, bool kGradFromFirst>
void packGather(double* rec, NodeRange range, const double* const vL[3], const double* const vn[3],
                const double* const vGrad[3]) {
  using S = GatherSlots<Dim, kVelocity, kMove, kGradient, kGradFromFirst>;
  constexpr int W = kSlotDoubles<Dim>;
  for (std::int64_t n = range.lo; n < range.hi; ++n) {
    double* r = rec + S::kStride * n;
    const auto slot = [&](int s, const double* const f[3]) {
      for (int d = 0; d < Dim; ++d) r[s * W + d] = f[d][n];
      for (int d = Dim; d < W; ++d) r[s * W + d] = 0.0;
    };
    if constexpr (S::kFirst) slot(0, vL);
    if constexpr (kVelocity) slot(S::kOld, vn);
    if constexpr (kGradient && !kGradFromFirst) slot(S::kGrad, vGrad);
  }
}

/// Zeroes the records of `range` (stride `stride` doubles) for the next scatter.
inline void clearRecords(double* rec, NodeRange range, int stride) {
  if (range.hi > range.lo)
    std::memset(rec + stride * range.lo, 0, sizeof(double) * static_cast<std::size_t>(stride * (range.hi - range.lo)));
}

/// gridToParticles on gather records (packGather) for 2D and 3D: the sums of the scalar kernel
/// as vector lanes, vnew and vold over the directions, L by columns (L[.][b] += v grad_b).
template <int Dim, bool kVelocity, bool kMove, bool kGradient, bool kGradFromFirst, class Src>
void gridToRecords(const Src& src, ParticleSet& p, std::size_t begin, std::size_t end, const GridGeom& g,
                   const double* rec, double dt, double flip) {
  using S = GatherSlots<Dim, kVelocity, kMove, kGradient, kGradFromFirst>;
  using V = std::conditional_t<Dim == 2, v2d, v4d>;
  constexpr int W = kSlotDoubles<Dim>;
  for (std::size_t i = begin; i < end; ++i) {
    // 2D: vnew and vold side by side in one vector when both are gathered (their slots are
    // adjacent), L as (L_xx, L_yx, L_xy, L_yy) += (v_x, v_y, v_x, v_y) (gx, gx, gy, gy).
    // 3D: vnew, vold and the columns of L, each a vector over the directions.
    V vnew{}, vold{}, Lc[3] = {};
    v4d vv{}, L4{};
    src.forNodesV(i, g, [&](std::int64_t n, v4d wg) {
      const double* r = rec + S::kStride * n;
      const v4d wv = splat<0>(wg);
      if constexpr (Dim == 2) {
        const auto lo = [](v4d v) { return __builtin_shufflevector(v, v, 0, 1); };
        if constexpr (S::kFirst && kVelocity)
          vv += wv * loadVec<v4d>(r);
        else if constexpr (S::kFirst)
          vnew += lo(wv) * loadVec<v2d>(r);
        if constexpr (kGradient) {
          const v2d vg = loadVec<v2d>(r + S::kGrad * W);
          L4 += __builtin_shufflevector(vg, vg, 0, 1, 0, 1) * __builtin_shufflevector(wg, wg, 1, 1, 2, 2);
        }
      } else {
        if constexpr (S::kFirst) vnew += wv * loadVec<V>(r);
        if constexpr (kVelocity) vold += wv * loadVec<V>(r + S::kOld * W);
        if constexpr (kGradient) {
          const V vg = loadVec<V>(r + S::kGrad * W);
          Lc[0] += vg * splat<1>(wg);
          Lc[1] += vg * splat<2>(wg);
          Lc[2] += vg * splat<3>(wg);
        }
      }
    });
    if constexpr (Dim == 2) {
      if constexpr (S::kFirst && kVelocity) {
        vnew = V{vv[0], vv[1]};
        vold = V{vv[2], vv[3]};
      }
      Lc[0] = V{L4[0], L4[1]};
      Lc[1] = V{L4[2], L4[3]};
    }
    writeBackParticle<Dim, kVelocity, kMove, kGradient>(p, i, vnew, vold, dt, flip,
                                                        [&](int a, int b) { return Lc[b][a]; });
  }
}

}  // namespace mpmice::mpm::kernels

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
