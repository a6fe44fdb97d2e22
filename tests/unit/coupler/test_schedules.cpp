// Each MPM-ICE schedule (src/couplings/volume/schedule/) runs over a recording transport: the
// exchange points in the order the schedule moves them, and where each falls in the step (has
// the solid / the fluid taken its step yet?). The same schedule object runs with both sides
// (in memory: copies) and with one side (MPMD: sends and receives), and the one-side orders
// mirror each other, so the MPMD programs meet at every exchange point.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "coupler/transport/in_memory_transport.h"
#include "couplings/volume/schedule/coupling_schedule.h"
#include "serial_mpi.h"

namespace mpmice::coupler {
namespace {

/// Records every move and trade; copies when both sides are here, leaves a lone side's input
/// as it is. `verdicts`: what a lone fluid side hears from the solid ("done" after n passes).
class RecordingTransport final : public Transport {
 public:
  RecordingTransport(const Sides& s, double t0) : sides_(s), t0_(t0) {}
  void move(std::span<const core::Field* const> from, std::span<core::Field* const> to,
            std::span<const int> components, int tag, const std::string& what) override {
    const std::string kind = !from.empty() && !to.empty() ? "copy" : !from.empty() ? "send" : "receive";
    log.push_back(kind + " " + what.substr(0, what.find(" of ")) + " [" + stepped() + "]");
    tags.push_back(tag);
    if (!from.empty() && !to.empty()) memory_.move(from, to, components, tag, what);
  }
  std::vector<double> trade(const std::vector<double>& mine, const std::string& what) override {
    log.push_back("trade " + what);
    if (what == "verdict of the iteration" && !sides_.solid) return {++passes_ >= fluidPassesUntilDone ? 1.0 : 0.0};
    return mine;
  }
  [[nodiscard]] bool inMemory() const override { return sides_.solid && sides_.fluid; }

  std::vector<std::string> log;
  std::vector<int> tags;
  int fluidPassesUntilDone = 1;

 private:
  std::string stepped() const {
    std::string s;
    if (sides_.solid) s += std::string("solid ") + (sides_.solid->solver().time() > t0_ ? "stepped" : "not yet");
    if (sides_.solid && sides_.fluid) s += ", ";
    if (sides_.fluid) s += std::string("fluid ") + (sides_.fluid->solver().time() > t0_ ? "stepped" : "not yet");
    return s;
  }
  Sides sides_;
  double t0_;
  int passes_ = 0;
  InMemoryTransport memory_;
};

struct CoupledPair {
  core::Scene scene;
  core::Comm comm{MPI_COMM_SELF};
  std::unique_ptr<mpm::MpmSolver> mpm;
  std::unique_ptr<ice::IceSolver> ice;
  std::unique_ptr<SolidSide> solid;
  std::unique_ptr<FluidSide> fluid;

  CoupledPair(core::Schedule schedule, bool withSolid, bool withFluid) : scene(core::loadScene(TINY_CYLINDER)) {
    scene.coupling.schedule = schedule;
    scene.coupling.max_iterations = 3;
    scene.coupling.accept_unconverged = true;
    if (withSolid) {
      mpm = std::make_unique<mpm::MpmSolver>(scene, comm);
      solid = std::make_unique<SolidSide>(*mpm);
    }
    if (withFluid) {
      ice = std::make_unique<ice::IceSolver>(scene, comm);
      fluid = std::make_unique<FluidSide>(*ice, scene);
    }
  }
  [[nodiscard]] Sides sides() const { return {solid.get(), fluid.get()}; }
  [[nodiscard]] double dt() const {
    double d = 1e30;
    if (solid) d = std::min(d, solid->stableTimeStep());
    if (fluid) d = std::min(d, fluid->stableTimeStep());
    return d;
  }
  /// The start, then `steps` steps; the log of the last step only.
  std::vector<std::string> steps(int steps, int fluidPasses = 1) {
    {
      RecordingTransport start(sides(), 1e30);
      startCoupling(sides(), start);
      if (steps == 0) return start.log;
    }
    const auto schedule = makeSchedule(scene, comm);
    std::vector<std::string> log;
    for (int k = 0; k < steps; ++k) {
      const double t0 = solid ? solid->solver().time() : fluid->solver().time();
      const double h = std::min(dt(), 1e-6);
      RecordingTransport tr(sides(), t0);
      tr.fluidPassesUntilDone = fluidPasses;
      schedule->step(sides(), tr, h);
      log = tr.log;
    }
    return log;
  }
};

using Log = std::vector<std::string>;

TEST(Schedules, TheStartIsCommonToEverySchedule) {
  CoupledPair r(core::Schedule::Monolithic, true, true);
  EXPECT_EQ(r.steps(0), (Log{"copy solid state [solid not yet, fluid not yet]",
                             "copy pressure force [solid not yet, fluid not yet]",
                             "copy exchange increments [solid not yet, fluid not yet]"}));
}

TEST(Schedules, MonolithicMovesFourPointsInsideTheStep) {
  CoupledPair r(core::Schedule::Monolithic, true, true);
  EXPECT_EQ(r.steps(2), (Log{"copy solid state [solid not yet, fluid not yet]",
                             "copy pressure force [solid not yet, fluid not yet]",
                             "copy Lagrangian momentum [solid not yet, fluid not yet]",
                             "copy exchange increments [solid not yet, fluid not yet]"}));
}

TEST(Schedules, ExplicitSerialStepsTheSolidFirst) {
  CoupledPair r(core::Schedule::ExplicitSerial, true, true);
  EXPECT_EQ(r.steps(2), (Log{"copy solid state [solid stepped, fluid not yet]",
                             "copy Lagrangian momentum [solid stepped, fluid not yet]",
                             "copy pressure force [solid stepped, fluid stepped]",
                             "copy exchange increments [solid stepped, fluid stepped]"}));
}

TEST(Schedules, ExplicitParallelHandsOverTheLastValuesBeforeEitherSteps) {
  CoupledPair r(core::Schedule::ExplicitParallel, true, true);
  EXPECT_EQ(r.steps(1), CoupledPair(core::Schedule::ExplicitSerial, true, true).steps(1));  // the first step: serial
  CoupledPair again(core::Schedule::ExplicitParallel, true, true);
  EXPECT_EQ(again.steps(2), (Log{"copy solid state [solid not yet, fluid not yet]",
                                 "copy Lagrangian momentum [solid not yet, fluid not yet]",
                                 "copy pressure force [solid stepped, fluid stepped]",
                                 "copy exchange increments [solid stepped, fluid stepped]"}));
}

TEST(Schedules, ImplicitSerialRepeatsTheSerialPassUntilTheVerdict) {
  CoupledPair r(core::Schedule::ImplicitSerial, true, true);
  const Log log = r.steps(2);
  const Log pass{"copy solid state [solid stepped, fluid not yet]",
                 "copy Lagrangian momentum [solid stepped, fluid not yet]",
                 "copy pressure force [solid stepped, fluid stepped]",
                 "copy exchange increments [solid stepped, fluid stepped]", "trade verdict of the iteration"};
  ASSERT_EQ(log.size() % pass.size(), 0u) << ::testing::PrintToString(log);
  ASSERT_GE(log.size(), pass.size());
  for (std::size_t i = 0; i < log.size(); ++i) EXPECT_EQ(log[i], pass[i % pass.size()]) << "entry " << i;
}

TEST(Schedules, ImplicitParallelIteratesOnEveryField) {
  CoupledPair r(core::Schedule::ImplicitParallel, true, true);
  const Log log = r.steps(2);
  const Log pass{"copy solid state [solid not yet, fluid not yet]",
                 "copy Lagrangian momentum [solid not yet, fluid not yet]",
                 "copy pressure force [solid stepped, fluid stepped]",
                 "copy exchange increments [solid stepped, fluid stepped]", "trade verdict of the iteration"};
  ASSERT_EQ(log.size() % pass.size(), 0u) << ::testing::PrintToString(log);
  for (std::size_t i = 0; i < log.size(); ++i) EXPECT_EQ(log[i], pass[i % pass.size()]) << "entry " << i;
}

/// The moves without the step markers, with sends and receives swapped on one side.
Log mirrored(const Log& log, bool swap) {
  Log out;
  for (std::string e : log) {
    e = e.substr(0, e.find(" ["));
    if (swap && e.rfind("send ", 0) == 0) e = "receive " + e.substr(5);
    else if (swap && e.rfind("receive ", 0) == 0) e = "send " + e.substr(8);
    out.push_back(e);
  }
  return out;
}

class OneSide : public ::testing::TestWithParam<core::Schedule> {};

TEST_P(OneSide, TheSolidAloneAndTheFluidAloneMeetAtEveryExchangePoint) {
  // Each side alone runs the same schedule object; what one sends, the other receives, in the
  // same order. Implicit: the solid decides after each pass; the fluid follows its verdict
  // (here: done after the solid's pass count).
  CoupledPair solid(GetParam(), true, false);
  const Log s = solid.steps(2);
  int passes = 0;
  for (const auto& e : s) passes += e == "trade verdict of the iteration";
  CoupledPair fluid(GetParam(), false, true);
  const Log f = fluid.steps(2, std::max(passes, 1));
  EXPECT_EQ(mirrored(s, false), mirrored(f, true));
  for (const auto& e : s) EXPECT_EQ(e.rfind("copy", 0), std::string::npos) << e;
  // Each step-side pair: in memory, the same points in the same order.
  CoupledPair both(GetParam(), true, true);
  Log m = mirrored(both.steps(2), false);
  Log sm = mirrored(s, false);
  for (auto& e : sm) e = "copy " + e.substr(e.find(' ') + 1);
  if (!core::isImplicit(GetParam())) {  // implicit: the pass counts may differ
    EXPECT_EQ(sm, m);
  }
}

INSTANTIATE_TEST_SUITE_P(Schedules, OneSide,
                         ::testing::Values(core::Schedule::Monolithic, core::Schedule::ExplicitSerial,
                                           core::Schedule::ExplicitParallel, core::Schedule::ImplicitSerial,
                                           core::Schedule::ImplicitParallel),
                         [](const auto& p) { return std::string(core::name(p.param)); });

TEST(Schedules, EveryPointAndSolidHasItsOwnTag) {
  CoupledPair r(core::Schedule::Monolithic, true, true);
  (void)r.steps(0);
  std::vector<int> tags;
  for (ExchangePoint p : kExchangePoints)
    for (int slot = 0; slot < 3; ++slot) tags.push_back(exchangeTag(p, slot));
  std::sort(tags.begin(), tags.end());
  EXPECT_EQ(std::adjacent_find(tags.begin(), tags.end()), tags.end());
}

}  // namespace
}  // namespace mpmice::coupler
