#include "core/parallel/mpi_session.h"

#include <cstdlib>

namespace mpmice::core {

namespace {
std::string& storedCommandLine() {
  static std::string line;
  return line;
}
std::string quoted(const std::string& a) {
  if (!a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-./=:,+@%") ==
                        std::string::npos)
    return a;
  std::string q = "'";
  for (char c : a) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}
}  // namespace

const std::string& MpiSession::commandLine() { return storedCommandLine(); }

MpiSession::MpiSession(int& argc, char**& argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) {
    if (i) line.push_back(' ');
    line.append(quoted(argv[i]));
  }
  storedCommandLine() = line;
  int initialized = 0;
  MPI_Initialized(&initialized);
  // Open MPI's OMPIO shared-memory shared-file-pointer component, unless the user chose one: nothing
  // here uses shared file pointers, and a run killed inside an HDF5 file's creation left its named
  // semaphore (/dev/shm/sem.OMPIO_<file>) at 0, on which the next run creating that file waited for
  // ever. scripts/mpirun passes the same; this covers a run started alone or by another mpirun.
  if (!initialized) setenv("OMPI_MCA_sharedfp", "^sm", 0);
  if (!initialized) MPI_Init(&argc, &argv);
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_ARE_FATAL);
}

MpiSession::~MpiSession() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) MPI_Finalize();
}

Comm MpiSession::world() const { return Comm(MPI_COMM_WORLD); }

int MpiSession::worldSize() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

int MpiSession::worldRank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

void MpiSession::abortAll(int code) {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

}  // namespace mpmice::core
