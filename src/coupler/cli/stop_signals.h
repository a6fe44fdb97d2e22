#pragma once
/// @brief SIGINT and SIGTERM recorded (not fatal) while a StopSignals lives, so a program that
/// started others (`coupler run`, `study`) can forward them to its children's process group and
/// wait for them; the previous handlers are restored after.
#include <csignal>
#include <string>

namespace mpmice::coupler {

class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;
  /// The last SIGINT / SIGTERM received while one lives (0: none).
  static int received();

 private:
  struct sigaction oldInt_ {}, oldTerm_ {};
};

/// "SIGINT", "SIGTERM", else "signal N".
std::string signalName(int sig);

}  // namespace mpmice::coupler
