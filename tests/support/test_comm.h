#pragma once
// The communicator of an MPI test executable, handed over by tests/support/mpi_gtest_main.cpp.
#include "core/parallel/comm.h"

namespace mpmice::test {
const core::Comm& comm();
}
