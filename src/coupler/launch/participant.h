#pragma once
/// @brief Joining an MPMD launch: this program's communicator and the inter-communicator to its peer.
///
/// `mpirun -np 2 mpm_solver s.yaml : -np 1 ice_solver s.yaml` starts two applications in one
/// MPI_COMM_WORLD. join() splits the world by application number (MPI_APPNUM) into each
/// program's own communicator and builds an inter-communicator to the other program; the
/// leaders trade names. A program started alone (one application) runs uncoupled.
#include <mpi.h>

#include <string>

#include "core/parallel/comm.h"

namespace mpmice::coupler {

class Participant {
 public:
  /// world: every process of the launch (from the launch layer). name: "mpm", "ice", ...
  static Participant join(const core::Comm& world, const std::string& name, double timeout);
  Participant(const Participant&) = delete;
  Participant& operator=(const Participant&) = delete;
  Participant(Participant&&) noexcept;
  Participant& operator=(Participant&&) noexcept;
  ~Participant();

  [[nodiscard]] bool coupled() const { return inter_ != MPI_COMM_NULL; }
  [[nodiscard]] const core::Comm& local() const { return local_; }
  [[nodiscard]] MPI_Comm inter() const { return inter_; }
  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] const std::string& peerName() const { return peerName_; }
  [[nodiscard]] int peerSize() const { return peerSize_; }
  /// World rank of this process's local rank 0 and of the peer's (for messages naming ranks).
  [[nodiscard]] int firstWorldRank() const { return firstWorld_; }
  [[nodiscard]] double timeout() const { return timeout_; }

 private:
  Participant() = default;
  core::Comm local_;
  MPI_Comm localRaw_ = MPI_COMM_NULL;
  MPI_Comm inter_ = MPI_COMM_NULL;
  std::string name_, peerName_;
  int peerSize_ = 0;
  int firstWorld_ = 0;
  double timeout_ = 60;
};

}  // namespace mpmice::coupler
