// The acceptance verdict (coupler/iteration/acceptance.h, preCICE's rule) and the implicit
// iteration over named data views (coupler/iteration/implicit_iteration.h): a failing strict
// measure overrules a holding suffices one; the iteration limit is an error unless the scene
// accepts unconverged steps.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "coupler/iteration/acceptance.h"
#include "coupler/iteration/implicit_iteration.h"
#include "serial_mpi.h"

namespace mpmice::coupler {
namespace {

TEST(Acceptance, StrictOverrulesSuffices) {
  const std::vector<MeasureOutcome> strictFailsSufficesHolds{{false, true}, {true, false}};
  EXPECT_FALSE(stepAccepted(5, 1, strictFailsSufficesHolds));
  const std::vector<MeasureOutcome> strictHoldsSufficesFails{{true, true}, {false, false}};
  EXPECT_FALSE(stepAccepted(5, 1, strictHoldsSufficesFails));  // not all hold, and no suffices holds
  const std::vector<MeasureOutcome> sufficesHoldsAlone{{false, false}, {true, false}};
  EXPECT_TRUE(stepAccepted(5, 1, sufficesHoldsAlone));  // one suffices holds, no strict fails
  const std::vector<MeasureOutcome> allHold{{true, true}, {true, false}};
  EXPECT_TRUE(stepAccepted(5, 1, allHold));
  EXPECT_FALSE(stepAccepted(1, 2, allHold));  // min_iterations first
  EXPECT_TRUE(stepAccepted(2, 2, allHold));
  EXPECT_FALSE(stepAccepted(5, 1, {}));  // no measure: nothing to accept on
}

// A fixed-point problem x = H(x) over two named fields: "slow" converges linearly (halving
// its distance to 1 every pass; never within 1e-12 in a few passes), "fast" is constant after
// the first pass (its measure holds from the second pass on).
struct TwoFields {
  std::vector<double> slow{0.0, 0.0}, fast{0.0};
  std::vector<DataView> views() { return {{"slow", {slow.data(), slow.size()}}, {"fast", {fast.data(), fast.size()}}}; }
  void pass() {
    for (double& v : slow) v = 0.5 * (v + 1.0);
    fast[0] = 3.0;
  }
};

core::CouplingSpec spec(int maxIterations, bool acceptUnconverged) {
  core::CouplingSpec s;
  s.min_iterations = 1;
  s.max_iterations = maxIterations;
  s.accept_unconverged = acceptUnconverged;
  return s;  // acceleration none
}

const std::vector<core::ConvergenceSpec> kStrictSlowSufficesFast{{"slow", core::MeasureType::Absolute, 1e-12, true},
                                                                 {"fast", core::MeasureType::Absolute, 1e-12, false}};

TEST(ImplicitIteration, AFailingStrictMeasureKeepsIteratingToTheLimitAndStops) {
  const core::Comm self(MPI_COMM_SELF);
  ImplicitIteration it(spec(6, false), kStrictSlowSufficesFast, self);
  TwoFields f;
  int passes = 0, restores = 0;
  try {
    it.iterate(f.views(), "the step at t = 0.25", [&] { f.pass(), ++passes; }, [&] { ++restores; }, [](bool) {});
    FAIL() << "a step whose strict measure fails was accepted";
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("the step at t = 0.25 did not converge in 6 iterations (coupling.max_iterations)"),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("slow"), std::string::npos) << m;
    EXPECT_NE(m.find("strict"), std::string::npos) << m;
    EXPECT_NE(m.find("accept_unconverged"), std::string::npos) << m;
  }
  EXPECT_EQ(passes, 6);    // the suffices measure held from pass 2 on: it did not stop the step
  EXPECT_EQ(restores, 5);  // every pass but the last starts again from the checkpoint
}

TEST(ImplicitIteration, AcceptUnconvergedEndsTheStepAtTheLimitUnconverged) {
  const core::Comm self(MPI_COMM_SELF);
  ImplicitIteration it(spec(4, true), kStrictSlowSufficesFast, self);
  TwoFields f;
  std::vector<bool> verdicts;
  const StepReport r = it.iterate(f.views(), "the step at t = 0", [&] { f.pass(); }, [] {},
                                  [&](bool done) { verdicts.push_back(done); });
  EXPECT_EQ(r.iterations, 4);
  EXPECT_FALSE(r.converged);
  ASSERT_EQ(r.residuals.size(), 2u);
  EXPECT_GT(r.residuals[0], 1e-12);  // slow: still moving
  EXPECT_EQ(r.residuals[1], 0.0);    // fast: held
  EXPECT_EQ(verdicts, (std::vector<bool>{false, false, false, true}));
}

TEST(ImplicitIteration, ASufficesMeasureEndsTheStepWhenNoStrictOneFails) {
  const core::Comm self(MPI_COMM_SELF);
  const std::vector<core::ConvergenceSpec> sufficesOnly{{"slow", core::MeasureType::Absolute, 1e-12, false},
                                                        {"fast", core::MeasureType::Absolute, 1e-12, false}};
  ImplicitIteration it(spec(50, false), sufficesOnly, self);
  TwoFields f;
  const StepReport r = it.iterate(f.views(), "the step at t = 0", [&] { f.pass(); }, [] {}, [](bool) {});
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 2);  // fast holds at the second pass
}

TEST(ImplicitIteration, ViewsOfOneNameAreMeasuredTogether) {
  std::vector<double> a{1, 2}, b{3}, c{4};
  const std::vector<DataView> v{{"x", {a.data(), a.size()}}, {"y", {b.data(), b.size()}}, {"x", {c.data(), c.size()}}};
  const Eigen::VectorXd x = gather(v, "x");
  ASSERT_EQ(x.size(), 3);
  EXPECT_EQ(x[2], 4.0);
  const Eigen::VectorXd all = pack(v);
  ASSERT_EQ(all.size(), 4);
  unpack(2 * all, v);
  EXPECT_EQ(a[1], 4.0);
  EXPECT_EQ(b[0], 6.0);
  EXPECT_EQ(c[0], 8.0);
}

}  // namespace
}  // namespace mpmice::coupler
