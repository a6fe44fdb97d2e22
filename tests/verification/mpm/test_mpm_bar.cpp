// Vibrating bar (benchmarks.md): centre-of-mass velocity against the exact solution, energy drift,
// error under refinement and the observed order for each shape function (reported).
#include <gtest/gtest.h>

#include <cstdio>

#include "mpm_problems.h"

using namespace mpmice;
namespace pr = mpmice::mpm::problems;

namespace {
struct MpiGuard {
  MpiGuard() { int i = 0; MPI_Initialized(&i); if (!i) MPI_Init(nullptr, nullptr); }
  ~MpiGuard() { int f = 0; MPI_Finalized(&f); if (!f) MPI_Finalize(); }
} g_mpi;

std::vector<pr::BarResult> study(const std::string& shape, const std::string& update, std::vector<double>& hs) {
  std::vector<pr::BarResult> r;
  for (int cells : {13, 25, 50}) {
    const auto s = pr::barScene(cells, shape, update);
    hs.push_back(s.mesh.dx(0));
    r.push_back(pr::runBar(s, core::Comm(MPI_COMM_SELF)));
  }
  std::vector<double> es;
  for (auto& x : r) es.push_back(x.error);
  std::printf("[bar %s %s] errors %.3e %.3e %.3e, order %.2f, energy drift %.2e %.2e %.2e\n", shape.c_str(),
              update.c_str(), es[0], es[1], es[2], pr::observedOrder(hs, es), r[0].energyDrift, r[1].energyDrift,
              r[2].energyDrift);
  return r;
}
}  // namespace

TEST(VibratingBar, SplinesConvergeFirstOrder) {
  for (const char* shape : {"bspline2", "bspline3"}) {
    std::vector<double> hs;
    const auto r = study(shape, "usl", hs);
    EXPECT_LT(r[1].error, r[0].error) << shape;
    EXPECT_LT(r[2].error, r[1].error) << shape;
    EXPECT_LT(r[2].error, 0.05) << shape;
    EXPECT_GT(pr::observedOrder(hs, {r[0].error, r[1].error, r[2].error}), 0.9) << shape;
    EXPECT_LT(r[2].energyDrift, 0.005) << shape;
  }
}

TEST(VibratingBar, GimpMostAccurate) {
  std::vector<double> hs;
  const auto r = study("gimp", "usl", hs);
  EXPECT_LT(r[1].error, r[0].error);
  EXPECT_LT(r[2].error, r[1].error);
  EXPECT_LT(r[2].error, 0.01);
  EXPECT_LT(r[2].energyDrift, 0.005);
}

TEST(VibratingBar, LinearBoundedByCellCrossing) {
  // Linear hats: the error is dominated by cell-crossing noise once particles cross nodes, so it
  // does not decrease monotonically; assert the coarse-grid accuracy and report the rest.
  std::vector<double> hs;
  const auto r = study("linear", "musl", hs);  // USL + linear hats is unstable here (tiny-mass nodes)
  EXPECT_LT(r[0].error, 0.03);
  EXPECT_LT(r[1].error, 0.01);
  EXPECT_LT(r[2].error, 0.1);
}
