#pragma once
/// @brief The launch layer: initialises and finalises MPI for a program.
///
/// This is the only place in the project that names MPI_COMM_WORLD. Programs create one
/// MpiSession in main() and pass world() (or a sub-communicator split from it by the coupler's
/// launch code) to the libraries.
#include <string>

#include "core/parallel/comm.h"

namespace mpmice::core {

class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  /// Every process of the launch (all programs of an MPMD launch).
  [[nodiscard]] Comm world() const;
  /// This program's command line as given (arguments shell-quoted where needed), for the run
  /// record; empty before a session exists.
  [[nodiscard]] static const std::string& commandLine();
  /// The size of the whole launch and this process's rank in it (both programs of an MPMD
  /// launch), for the run's description (core/io/run_metadata.h).
  [[nodiscard]] static int worldSize();
  [[nodiscard]] static int worldRank();
  /// Aborts every process of the launch with the given code.
  [[noreturn]] static void abortAll(int code);
};

}  // namespace mpmice::core
