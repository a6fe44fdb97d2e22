// Colliding elastic disks (Sulsky 1994): total energy over the collision per update scheme.
// FLIP keeps the total within a few percent; PIC dissipates a large part of it.
#include <gtest/gtest.h>

#include <cstdio>

#include "mpm_problems.h"
#include "serial_mpi.h"

using namespace mpmice;
namespace pr = mpmice::mpm::problems;

namespace {

struct Summary {
  double e0, emin, emax, eend, kmin;
};
Summary run(const std::string& update, double flip) {
  const auto es = pr::runDisks(pr::disksScene(20, update, flip), core::Comm(MPI_COMM_SELF));
  Summary s{es.front().kinetic + es.front().strain, 1e300, 0, es.back().kinetic + es.back().strain, 1e300};
  for (const auto& e : es) {
    s.emin = std::min(s.emin, e.kinetic + e.strain);
    s.emax = std::max(s.emax, e.kinetic + e.strain);
    s.kmin = std::min(s.kmin, e.kinetic);
  }
  std::printf("[disks %s flip %g] E0 %.4f  min %.4f  max %.4f  end %.4f  (%+.2f%%)  KE min %.4f\n",
              update.c_str(), flip, s.e0, s.emin, s.emax, s.eend, 100 * (s.eend - s.e0) / s.e0, s.kmin);
  return s;
}
}  // namespace

TEST(CollidingDisks, InitialKineticEnergy) {
  const auto s = run("usl", 1.0);
  EXPECT_NEAR(s.e0, 2.513, 0.05 * 2.513);  // benchmarks.md (exact disks; particles sample them)
  EXPECT_LT(s.kmin, 0.5 * s.e0);           // the disks do collide and store strain energy
}

TEST(CollidingDisks, FlipConservesPicDissipates) {
  for (const char* up : {"usf", "usl", "musl"}) {
    const auto flip = run(up, 1.0);
    EXPECT_LT(std::fabs(flip.eend - flip.e0) / flip.e0, 0.08) << up;
    EXPECT_LT(flip.emax, 1.05 * flip.e0) << up;
    const auto pic = run(up, 0.0);
    EXPECT_LT(pic.eend, 0.9 * pic.e0) << up;
  }
}
