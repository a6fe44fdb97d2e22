#pragma once
// For plain (non-MPI-launched) gtest executables whose code takes a communicator: initialises MPI
// once before the tests and finalises it after them. Tests use MPI_COMM_SELF through their Comm.
#include <mpi.h>

namespace mpmice::test {
struct SerialMpi {
  SerialMpi() {
    int i = 0;
    MPI_Initialized(&i);
    if (!i) MPI_Init(nullptr, nullptr);
  }
  ~SerialMpi() {
    int f = 0;
    MPI_Finalized(&f);
    if (!f) MPI_Finalize();
  }
};
inline SerialMpi g_serialMpi;
}  // namespace mpmice::test
