#pragma once
/// @brief Starting programs without a shell: an argv vector through posix_spawn, the line shown
/// to the user shell-quoted (single quotes, safe to copy and paste).
///
/// A started Process runs in its own process group (so a signal forwarded to the group reaches
/// mpirun and everything it started), with stdin from /dev/null and stdout + stderr into one
/// pipe that the caller reads (`coupler run` streams it through and parses mpirun's failure text).
#include <string>
#include <sys/types.h>
#include <vector>

namespace mpmice::coupler {

/// `a` as one shell word: unchanged when it holds only characters no shell treats specially
/// (letters, digits, `_@%+=:,./-`), otherwise in single quotes (a `'` inside becomes `'\''`).
std::string shellQuote(const std::string& a);

/// The words joined by spaces, each shellQuote'd.
std::string shellLine(const std::vector<std::string>& argv);

class Process {
 public:
  /// Starts argv[0] (looked up in PATH when it has no '/') with argv; `env` entries
  /// ("NAME=value") replace or extend the environment. Throws std::runtime_error naming the
  /// program when it cannot be started.
  explicit Process(const std::vector<std::string>& argv, const std::vector<std::string>& env = {});
  ~Process();
  Process(const Process&) = delete;
  Process& operator=(const Process&) = delete;

  [[nodiscard]] pid_t pid() const { return pid_; }
  /// The read end of the output pipe (stdout and stderr), -1 once closed.
  [[nodiscard]] int output() const { return fd_; }
  /// Sends `sig` to the process group.
  void signalGroup(int sig) const;
  /// Non-blocking: true once the process has ended (it stays a zombie until wait()).
  [[nodiscard]] bool ended() const;
  /// Waits for the process, first killing whatever is left of its group; returns the exit
  /// status in the shell's convention (128 + signal number when killed by a signal).
  int wait();

 private:
  pid_t pid_ = -1;
  int fd_ = -1;
  bool reaped_ = false;
};

/// Runs argv to its end with stdout + stderr into `logPath`; returns its exit status.
int runToFile(const std::vector<std::string>& argv, const std::string& logPath, const std::vector<std::string>& env = {});

/// What a bounded run measured (runToFileWithin).
struct TimedRun {
  int status = 0;             // the shell's convention (128 + signal number when killed)
  bool timedOut = false;      // the time limit ended it (its group got SIGTERM, then SIGKILL)
  int stoppedBy = 0;          // a SIGINT / SIGTERM recorded by a live StopSignals, forwarded to its group
  double wallSeconds = 0;     // from start to reaping
  double cpuSeconds = 0;      // wait4's user + system time of the process and of every descendant
                              // it waited for (an mpirun's ranks included): the run's CPU cost
  long peakRssKb = 0;         // wait4's ru_maxrss: the largest resident set of the process or of
                              // any descendant it waited for (the largest one, not a sum)
};

/// runToFile with a time limit: argv starts in its own process group with stdout + stderr into
/// `logPath`; after `limitSeconds` (> 0) the group gets SIGTERM and, 5 s later, SIGKILL. A
/// SIGINT / SIGTERM recorded by a live StopSignals (stop_signals.h) is forwarded to the group
/// the same way (SIGKILL 5 s later).
TimedRun runToFileWithin(const std::vector<std::string>& argv, const std::string& logPath, double limitSeconds,
                         const std::vector<std::string>& env = {});

}  // namespace mpmice::coupler
