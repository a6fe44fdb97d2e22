// GoogleTest main for tests launched under MPI: initialises MPI through the launch layer, runs the
// tests on every rank, prints results on rank 0 only, and fails the launch if any rank failed.
#include <gtest/gtest.h>

#include "core/parallel/mpi_session.h"
#include "test_comm.h"

namespace {
mpmice::core::Comm g_comm;
}
const mpmice::core::Comm& mpmice::test::comm() { return g_comm; }

int main(int argc, char** argv) {
  mpmice::core::MpiSession session(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  const auto world = session.world();
  g_comm = world;
  if (!world.root()) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const int local = RUN_ALL_TESTS();
  return world.max(local);
}
