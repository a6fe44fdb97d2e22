// 1 rank and N ranks give the same figures (to 1e-10 relative): each problem runs on the test's
// communicator (decomposed, particles migrating) and on rank 0 alone, and the figures are compared,
// for every shape function family (B-splines and GIMP sum the node layer outside the mesh across
// ranks; beyond symmetry planes it is folded onto the mirror nodes).
#include <gtest/gtest.h>

#include "mpm_problems.h"
#include "test_comm.h"

using namespace mpmice;
namespace pr = mpmice::mpm::problems;

namespace {
template <class F>
void compare(const char* what, F run) {
  const auto& world = test::comm();
  const double parallel = run(world);
  double serial = 0;
  if (world.root()) serial = run(core::Comm(MPI_COMM_SELF));
  if (world.root()) {
    std::printf("[%s] %d ranks %.15e, 1 rank %.15e\n", what, world.size(), parallel, serial);
    EXPECT_NEAR(parallel, serial, 1e-10 * std::fabs(serial)) << what;
  }
}
}  // namespace

TEST(RankIndependence, VibratingBarError) {
  compare("bar gimp", [](const core::Comm& c) { return pr::runBar(pr::barScene(25, "gimp"), c).error; });
  compare("bar linear", [](const core::Comm& c) { return pr::runBar(pr::barScene(25, "linear"), c).error; });
  // B-splines reach the node layer outside the mesh, which the rank at that face owns.
  compare("bar bspline2", [](const core::Comm& c) { return pr::runBar(pr::barScene(25, "bspline2"), c).error; });
  compare("bar bspline3", [](const core::Comm& c) { return pr::runBar(pr::barScene(25, "bspline3"), c).error; });
}

TEST(RankIndependence, LameError) {
  compare("lame linear", [](const core::Comm& c) { return pr::runLame(pr::lameScene(0.1, "linear"), c).error; });
  // 2 x 2 process grid: ghost layers beyond both symmetry planes (folded onto their mirror
  // nodes before the ghost sum, mirrored after it), and the corner.
  compare("lame gimp", [](const core::Comm& c) { return pr::runLame(pr::lameScene(0.1, "gimp"), c).error; });
  compare("lame bspline2", [](const core::Comm& c) { return pr::runLame(pr::lameScene(0.1, "bspline2"), c).error; });
  compare("lame bspline3", [](const core::Comm& c) { return pr::runLame(pr::lameScene(0.1, "bspline3"), c).error; });
}

TEST(RankIndependence, DisksEnergy) {
  compare("disks musl", [](const core::Comm& c) {
    const auto es = pr::runDisks(pr::disksScene(20, "musl", 1.0, "linear", 1.5), c);
    return es.back().kinetic + es.back().strain;
  });
  compare("disks bspline2 usl", [](const core::Comm& c) {
    const auto es = pr::runDisks(pr::disksScene(20, "usl", 1.0, "bspline2", 1.5), c);
    return es.back().kinetic + es.back().strain;
  });
}
