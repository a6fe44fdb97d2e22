// MPM verification studies at full size (the figures of docs/mpm.md).
//
// Sample runs:  build/benchmarks/mpm/mpm_study bar
//               build/benchmarks/mpm/mpm_study lame [linear|gimp|bspline2|bspline3 ...]
//               build/benchmarks/mpm/mpm_study lame_layers [shapes]   (where the Lame error sits)
//               build/benchmarks/mpm/mpm_study lame_bands [shapes]    (error by distance from the surfaces)
//               build/benchmarks/mpm/mpm_study disks
//               scripts/mpirun -np 4 build/benchmarks/mpm/mpm_study lame gimp
// 1. bar:   vibrating bar, 4 resolutions per shape function: v_cm error, energy drift, order.
// 2. lame:  Lame cylinder, dx = 0.05 ... 0.00625: Eq. 13 error and order per shape function.
//           Env: LAME_COARSE=1 (3 grids), LAME_DX, LAME_PPC (2), LAME_END (4e-3), LAME_DAMP (1e4),
//           LAME_RAMP (1e-3), LAME_FLIP, LAME_UPDATE; LAME_PROFILE=1 (lame_bands): the radial profile.
// 3. disks: colliding disks, energy over the collision per update scheme (FLIP and PIC).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <string>
#include <vector>

#include "mpm_problems.h"
#include "core/parallel/mpi_session.h"

using namespace mpmice;
using namespace mpmice::mpm;
namespace pr = mpmice::mpm::problems;

namespace {
double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Lame grid spacings: the four of the study, LAME_COARSE = the test's three, LAME_DX = one.
std::vector<double> lameSpacings(std::vector<double> dxs) {
  if (const char* e = std::getenv("LAME_DX")) dxs = {std::atof(e)};
  if (std::getenv("LAME_COARSE")) dxs = {0.05, 0.025, 0.0125};
  return dxs;
}
}  // namespace

int main(int argc, char** argv) {
  core::MpiSession session(argc, argv);
  const core::Comm comm = session.world();
  const std::string what = argc > 1 ? argv[1] : "bar";
  std::vector<std::string> shapes;
  for (int a = 2; a < argc; ++a) shapes.emplace_back(argv[a]);
  if (shapes.empty()) shapes = {"linear", "gimp", "bspline2", "bspline3"};
  const bool root = comm.root();
  try {
    if (what == "bar") {
      // 1. Vibrating bar.
      if (root) std::printf("| shape | cells | particles | steps | v_cm error | energy drift | order | wall [s] |\n|---|---|---|---|---|---|---|---|\n");
      for (const auto& sh : shapes) {
        std::vector<double> hs, es;
        for (int cells : {13, 25, 50, 100}) {
          const auto t0 = std::chrono::steady_clock::now();
          const char* up = std::getenv("MPM_UPDATE");
          const auto s = pr::barScene(cells, sh, up ? up : "usl");
          const auto r = pr::runBar(s, comm);
          hs.push_back(s.mesh.dx(0));
          es.push_back(r.error);
          const std::string order = hs.size() > 1 ? std::to_string(pr::observedOrder(
                                                        {hs[hs.size() - 2], hs.back()}, {es[es.size() - 2], es.back()}))
                                                  : "";
          if (root)
            std::printf("| %s | %d | %lld | %ld | %.4e | %.3e | %s | %.2f |\n", sh.c_str(), cells,
                        r.particles, r.steps, r.error, r.energyDrift, order.c_str(), seconds(t0));
        }
        if (root) std::printf("| %s | fitted order over 4 grids | | | | | %.3f | |\n", sh.c_str(), pr::observedOrder(hs, es));
      }
    } else if (what == "lame") {
      // 2. Lame cylinder.
      if (root) std::printf("| shape | dx | particles | steps | Eq. 13 error | order | wall [s] |\n|---|---|---|---|---|---|---|\n");
      const std::vector<double> dxs = lameSpacings({0.05, 0.025, 0.0125, 0.00625});
      for (const auto& sh : shapes) {
        std::vector<double> hs, es;
        for (double dx : dxs) {
          const auto t0 = std::chrono::steady_clock::now();
          auto env = [](const char* k, double d) { const char* v = std::getenv(k); return v ? std::atof(v) : d; };
          auto scene = pr::lameScene(dx, sh, env("LAME_RAMP", 1e-3), env("LAME_END", 4.0e-3),
                                     env("LAME_DAMP", 1.0e4), static_cast<int>(env("LAME_PPC", 2)));
          scene.mpm.flip = env("LAME_FLIP", scene.mpm.flip);
          if (const char* u = std::getenv("LAME_UPDATE")) scene.mpm.update = u;
          const auto r = pr::runLame(scene, comm);
          hs.push_back(dx);
          es.push_back(r.error);
          const std::string order = hs.size() > 1 ? std::to_string(pr::observedOrder(
                                                        {hs[hs.size() - 2], hs.back()}, {es[es.size() - 2], es.back()}))
                                                  : "";
          if (root)
            std::printf("| %s | %g | %lld | %ld | %.4e | %s | %.2f |\n", sh.c_str(), dx, r.particles,
                        r.steps, r.error, order.c_str(), seconds(t0));
        }
        if (root && hs.size() > 1) std::printf("| %s | fitted order over %zu grids | | | | %.3f | |\n", sh.c_str(), hs.size(), pr::observedOrder(hs, es));
      }
    } else if (what == "lame_layers") {
      // 2b. Where the Lame error sits: Eq. 13 sums split into the inner loaded layer, the outer
      //     free-surface layer (one particle layer each) and the interior, as shares of the total.
      if (root) std::printf("| shape | dx | Eq. 13 error | inner layer | outer layer | interior | interior mean bias | interior within 2 dx of the symmetry planes |\n|---|---|---|---|---|---|---|---|\n");
      for (const auto& sh : shapes)
        for (double dx : lameSpacings({0.05, 0.025, 0.0125})) {
          auto env = [](const char* k, double d) { const char* v = std::getenv(k); return v ? std::atof(v) : d; };
          const int ppc = static_cast<int>(env("LAME_PPC", 2));
          const auto scene = pr::lameScene(dx, sh, env("LAME_RAMP", 1e-3), env("LAME_END", 4.0e-3), env("LAME_DAMP", 1.0e4), ppc);
          MpmSolver solver(scene, comm);
          while (solver.time() < scene.time.end * (1 - 1e-12)) solver.advance(scene.time.end);
          pr::Lame l;
          const auto& p = solver.particles();
          std::vector<double> acc(5, 0.0);
          for (std::size_t i = 0; i < p.size(); ++i) {
            const double r = std::hypot(p.x[0][i], p.x[1][i]);
            const double e = (p.stress[kXX][i] + p.stress[kYY][i] - l.sumExact()) / l.sumExact();
            const int bin = r < l.ri + dx / ppc ? 0 : (r > l.ro - dx / ppc ? 1 : 2);
            acc[bin] += std::fabs(e);
            if (bin == 2) acc[3] += e;
            if (bin == 2 && std::min(p.x[0][i], p.x[1][i]) < 2 * dx) acc[4] += std::fabs(e);
          }
          comm.sumInPlace(acc);
          const double n = static_cast<double>(solver.globalParticleCount());
          if (root)
            std::printf("| %s | %g | %.4f | %.4f | %.4f | %.4f | %+.4f | %.4f |\n", sh.c_str(), dx, (acc[0] + acc[1] + acc[2]) / n,
                        acc[0] / n, acc[1] / n, acc[2] / n, acc[3] / n, acc[4] / n);
        }
    } else if (what == "lame_bands") {
      // 2c. Eq. 13 sum by distance from the nearer curved surface, in cells: [0,1) [1,2) [2,4)
      //     [4,8) [8,...) dx, with the signed mean of each band.
      if (root) std::printf("| shape | dx | Eq. 13 error | 0-1 dx | 1-2 dx | 2-4 dx | 4-8 dx | >= 8 dx | mean bias >= 8 dx |\n|---|---|---|---|---|---|---|---|---|\n");
      for (const auto& sh : shapes)
        for (double dx : lameSpacings({0.05, 0.025, 0.0125})) {
          auto env = [](const char* k, double d) { const char* v = std::getenv(k); return v ? std::atof(v) : d; };
          const auto scene = pr::lameScene(dx, sh, env("LAME_RAMP", 1e-3), env("LAME_END", 4.0e-3), env("LAME_DAMP", 1.0e4),
                                           static_cast<int>(env("LAME_PPC", 2)));
          MpmSolver solver(scene, comm);
          while (solver.time() < scene.time.end * (1 - 1e-12)) solver.advance(scene.time.end);
          pr::Lame l;
          const auto& p = solver.particles();
          std::vector<double> acc(6, 0.0);
          for (std::size_t i = 0; i < p.size(); ++i) {
            const double r = std::hypot(p.x[0][i], p.x[1][i]);
            const double e = (p.stress[kXX][i] + p.stress[kYY][i] - l.sumExact()) / l.sumExact();
            const double t = std::min(r - l.ri, l.ro - r) / dx;
            const int bin = t < 1 ? 0 : t < 2 ? 1 : t < 4 ? 2 : t < 8 ? 3 : 4;
            acc[bin] += std::fabs(e);
            if (bin == 4) acc[5] += e;
          }
          comm.sumInPlace(acc);
          const double n = static_cast<double>(solver.globalParticleCount());
          if (std::getenv("LAME_PROFILE")) {
            // By radius in bins of dx / 2: signed (sum - S) / S, sigma_r and sigma_theta against Lame's
            // (the format of `cylinder_lame --profile`).
            const double h = 0.5 * dx, A = l.sumExact() / 2, B = l.P * l.ri * l.ri * l.ro * l.ro / (l.ro * l.ro - l.ri * l.ri);
            const int nb = static_cast<int>(std::ceil((l.ro - l.ri) / h)) + 2;
            std::vector<double> pr(6 * static_cast<std::size_t>(nb) + 27, 0.0);  // + interior by angle (10 degrees)
            double* ang = pr.data() + 6 * nb;
            for (std::size_t i = 0; i < p.size(); ++i) {
              const double r = std::hypot(p.x[0][i], p.x[1][i]), cs = p.x[0][i] / r, sn = p.x[1][i] / r;
              const auto b = static_cast<std::size_t>(std::clamp(static_cast<int>(std::floor((r - l.ri) / h)) + 1, 0, nb - 1));
              const double sxx = p.stress[kXX][i], syy = p.stress[kYY][i], sxy = p.stress[kXY][i];
              const double eq = (sxx + syy - l.sumExact()) / l.sumExact();
              pr[6 * b] += 1;
              pr[6 * b + 1] += eq;
              pr[6 * b + 2] += r;
              pr[6 * b + 3] += sxx * cs * cs + syy * sn * sn + 2 * sxy * sn * cs;
              pr[6 * b + 4] += sxx * sn * sn + syy * cs * cs - 2 * sxy * sn * cs;
              pr[6 * b + 5] += std::fabs(eq);
              if (std::min(r - l.ri, l.ro - r) >= 2 * dx) {
                const int k = std::clamp(static_cast<int>(std::atan2(p.x[1][i], p.x[0][i]) / (M_PI / 18)), 0, 8);
                ang[3 * k] += 1, ang[3 * k + 1] += eq, ang[3 * k + 2] += std::fabs(eq);
              }
            }
            comm.sumInPlace(pr);
            for (std::size_t b = 0; root && b < static_cast<std::size_t>(nb); ++b) {
              const double c = pr[6 * b];
              if (c == 0) continue;
              const double rm = pr[6 * b + 2] / c;
              std::printf("mpm_study: profile | %.5f | %.0f | %+.5f | %.5f | %.4f | %.4f | %.4f | %.4f |\n", rm, c, pr[6 * b + 1] / c,
                          pr[6 * b + 5] / c, pr[6 * b + 3] / c / 1e6, (A - B / (rm * rm)) / 1e6, pr[6 * b + 4] / c / 1e6,
                          (A + B / (rm * rm)) / 1e6);
            }
            if (root) {
              std::printf("mpm_study: interior (>= 2 dx from both surfaces) by angle, 10 degree bins: signed / mean abs:");
              for (int k = 0; k < 9; ++k)
                std::printf(" %+.4f/%.4f", ang[3 * k] > 0 ? ang[3 * k + 1] / ang[3 * k] : 0.0, ang[3 * k] > 0 ? ang[3 * k + 2] / ang[3 * k] : 0.0);
              std::printf("\n");
            }
          }
          if (root)
            std::printf("| %s | %g | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %+.4f |\n", sh.c_str(), dx,
                        (acc[0] + acc[1] + acc[2] + acc[3] + acc[4]) / n, acc[0] / n, acc[1] / n, acc[2] / n, acc[3] / n,
                        acc[4] / n, acc[5] / n);
        }
    } else if (what == "disks") {
      // 3. Colliding disks.
      if (root) std::printf("| update | flip | E(0) [J/m] | min E | max E | E(end) | change | KE min |\n|---|---|---|---|---|---|---|---|\n");
      for (const char* up : {"usf", "usl", "musl"})
        for (double flip : {1.0, 0.0}) {
          const auto es = pr::runDisks(pr::disksScene(40, up, flip), comm);
          double mn = 1e300, mx = 0, kmin = 1e300;
          for (const auto& e : es) {
            mn = std::min(mn, e.kinetic + e.strain);
            mx = std::max(mx, e.kinetic + e.strain);
            kmin = std::min(kmin, e.kinetic);
          }
          const double e0 = es.front().kinetic + es.front().strain, e1 = es.back().kinetic + es.back().strain;
          if (root)
            std::printf("| %s | %g | %.4f | %.4f | %.4f | %.4f | %+.2f%% | %.4f |\n", up, flip, e0, mn, mx, e1,
                        100 * (e1 - e0) / e0, kmin);
        }
    } else {
      if (root) std::fprintf(stderr, "mpm_study: unknown study '%s'; valid: bar, lame, lame_layers, lame_bands, disks\n", what.c_str());
      return 2;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mpm_study: %s\n", e.what());
    return 1;
  }
  return 0;
}
