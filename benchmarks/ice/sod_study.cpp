// ice_sod_study: the Sod convergence study beyond the tests' four grids (100 .. 3200 cells) for
// first and second order advection, explicit and semi-implicit pressure; L1 density error at
// t = 0.2, the order between successive grids, steps and wall time. Results: docs/ice.md.
//   ice_sod_study [max_cells=3200]
#include <mpi.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "ice_test_scenes.h"

using namespace mpmice;

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  const int maxN = argc > 1 ? std::atoi(argv[1]) : 3200;
  const test::Primitive L{1, 0, 1}, R{0.125, 0, 0.1};
  const test::ExactRiemann ex(L, R);
  std::printf("| advection | pressure | cells | steps | wall [s] | L1(rho) | order |\n|---|---|---|---|---|---|---|\n");
  for (const char* adv : {"first_order", "second_order"})
    for (const char* pr : {"explicit", "semi_implicit"}) {
      double prev = 0;
      for (int n = 100; n <= maxN; n *= 2) {
        const core::Scene sc = test::shockTube(n, L, R, 0.5, 0.2, {adv, pr});
        const auto t0 = std::chrono::steady_clock::now();
        ice::IceSolver s(sc, core::Comm(MPI_COMM_SELF));
        test::runToEnd(s, 0.2);
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const double err = test::l1Density(s, [&](double x) { return ex.sample((x - 0.5) / 0.2).rho; });
        if (prev > 0)
          std::printf("| %s | %s | %d | %ld | %.3f | %.3e | %.2f |\n", adv, pr, n, s.steps(), wall, err, std::log2(prev / err));
        else
          std::printf("| %s | %s | %d | %ld | %.3f | %.3e | |\n", adv, pr, n, s.steps(), wall, err);
        prev = err;
      }
    }
  MPI_Finalize();
  return 0;
}
