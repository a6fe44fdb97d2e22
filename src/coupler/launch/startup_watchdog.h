#pragma once
/// @brief A bound on the start of an MPMD launch: the collective calls that join the two programs
/// (MPI_Allgather, MPI_Comm_split, MPI_Intercomm_create) have no timeout of their own, so a
/// program stopped or hung before it joins would hold its peer for ever. The watchdog runs beside
/// them; if the join has not finished within coupling.timeout it prints one line naming this
/// program and what it waited for, and ends the process with status 1 (mpirun then ends the
/// whole launch, and `coupler run` names the side that reported).
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace mpmice::coupler {

class StartupWatchdog {
 public:
  /// program: this program's participant name; timeout: coupling.timeout [s].
  StartupWatchdog(std::string program, double timeout);
  ~StartupWatchdog();  // disarms
  StartupWatchdog(const StartupWatchdog&) = delete;
  StartupWatchdog& operator=(const StartupWatchdog&) = delete;

 private:
  std::mutex m_;
  std::condition_variable cv_;
  bool done_ = false;
  std::thread thread_;
};

/// Fault injection for the launch tests: MPMICE_FAULT_STALL_START=<name>:<seconds> makes the
/// participant called <name> sleep that long before it joins (a program stopped at start-up).
void maybeStallAtStart(const std::string& name);

}  // namespace mpmice::coupler
