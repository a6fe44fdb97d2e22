#include "coupler/cli/process.h"

#include "coupler/cli/stop_signals.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <spawn.h>
#include <stdexcept>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

namespace mpmice::coupler {

std::string shellQuote(const std::string& a) {
  const bool plain = !a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                       "0123456789_@%+=:,./-") == std::string::npos;
  if (plain) return a;
  std::string q(1, '\'');
  for (char c : a) {
    if (c == '\'') q.append("'\\''");
    else q.push_back(c);
  }
  q.push_back('\'');
  return q;
}

std::string shellLine(const std::vector<std::string>& argv) {
  std::string s;
  for (const auto& a : argv) {
    if (!s.empty()) s.push_back(' ');
    s.append(shellQuote(a));
  }
  return s;
}

namespace {

/// environ with `env` entries replacing those of the same name.
std::vector<std::string> mergedEnvironment(const std::vector<std::string>& env) {
  std::vector<std::string> all;
  for (char** e = environ; e && *e; ++e) {
    const std::string entry = *e;
    const std::string name = entry.substr(0, entry.find('='));
    bool replaced = false;
    for (const auto& x : env) replaced = replaced || x.substr(0, x.find('=')) == name;
    if (!replaced) all.push_back(entry);
  }
  all.insert(all.end(), env.begin(), env.end());
  return all;
}

std::vector<char*> pointers(std::vector<std::string>& words) {
  std::vector<char*> p;
  for (auto& w : words) p.push_back(w.data());
  p.push_back(nullptr);
  return p;
}

int shellStatus(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return 1;
}

/// posix_spawnp with stdin from /dev/null, stdout + stderr to `outFd`, in a new process group,
/// with default SIGINT/SIGTERM handling and an empty signal mask.
pid_t spawn(const std::vector<std::string>& argv, const std::vector<std::string>& env, int outFd) {
  if (argv.empty()) throw std::invalid_argument("spawn: empty command");
  std::vector<std::string> args = argv, envs = mergedEnvironment(env);
  auto argp = pointers(args);
  auto envp = pointers(envs);
  posix_spawn_file_actions_t fa;
  posix_spawnattr_t at;
  posix_spawn_file_actions_init(&fa);
  posix_spawnattr_init(&at);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&fa, outFd, 1);
  posix_spawn_file_actions_adddup2(&fa, outFd, 2);
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  sigaddset(&defaults, SIGPIPE);
  posix_spawnattr_setsigmask(&at, &none);
  posix_spawnattr_setsigdefault(&at, &defaults);
  posix_spawnattr_setpgroup(&at, 0);
  posix_spawnattr_setflags(&at, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  pid_t pid = -1;
  const int rc = posix_spawnp(&pid, args[0].c_str(), &fa, &at, argp.data(), envp.data());
  posix_spawn_file_actions_destroy(&fa);
  posix_spawnattr_destroy(&at);
  if (rc != 0) throw std::runtime_error("coupler: could not start " + argv[0] + ": " + std::strerror(rc));
  return pid;
}

}  // namespace

Process::Process(const std::vector<std::string>& argv, const std::vector<std::string>& env) {
  int p[2];
  if (pipe2(p, O_CLOEXEC) != 0) throw std::runtime_error(std::string("coupler: pipe: ") + std::strerror(errno));
  try {
    pid_ = spawn(argv, env, p[1]);
  } catch (...) {
    close(p[0]);
    close(p[1]);
    throw;
  }
  close(p[1]);
  fd_ = p[0];
}

Process::~Process() {
  if (!reaped_ && pid_ > 0) {
    signalGroup(SIGKILL);
    (void)wait();
  }
  if (fd_ >= 0) close(fd_);
}

void Process::signalGroup(int sig) const {
  if (pid_ > 0 && !reaped_) ::kill(-pid_, sig);
}

bool Process::ended() const {
  if (reaped_) return true;
  siginfo_t info{};
  // WNOWAIT: the ended process stays a zombie, so its pid (the group's id) cannot be reused yet.
  if (waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT) != 0) return false;
  return info.si_pid == pid_;
}

int Process::wait() {
  if (reaped_) return 0;
  siginfo_t info{};
  while (waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOWAIT) != 0 && errno == EINTR) {
  }
  ::kill(-pid_, SIGKILL);  // nothing of the group outlives its leader
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  reaped_ = true;
  return shellStatus(status);
}

namespace {
/// spawn() with stdout + stderr into `logPath` (created or truncated).
pid_t spawnToFile(const std::vector<std::string>& argv, const std::string& logPath, const std::vector<std::string>& env) {
  const int fd = open(logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("coupler: cannot write " + logPath + ": " + std::strerror(errno));
  pid_t pid = -1;
  try {
    pid = spawn(argv, env, fd);
  } catch (...) {
    close(fd);
    throw;
  }
  close(fd);
  return pid;
}
}  // namespace

int runToFile(const std::vector<std::string>& argv, const std::string& logPath, const std::vector<std::string>& env) {
  const pid_t pid = spawnToFile(argv, logPath, env);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return shellStatus(status);
}

TimedRun runToFileWithin(const std::vector<std::string>& argv, const std::string& logPath, double limitSeconds,
                         const std::vector<std::string>& env) {
  if (!(limitSeconds > 0)) throw std::invalid_argument("runToFileWithin: the time limit must be > 0 s");
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const pid_t pid = spawnToFile(argv, logPath, env);
  const auto seconds = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  TimedRun run;
  double killAt = limitSeconds;
  bool termSent = false;
  for (;;) {  // poll without reaping (the group's id stays reserved while it is a zombie)
    siginfo_t info{};
    const int rc = waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT);
    if (rc == 0 && info.si_pid == pid) break;
    if (rc != 0 && errno != EINTR) break;
    if (const int sig = StopSignals::received(); sig != 0 && run.stoppedBy == 0) {  // forwarded once
      run.stoppedBy = sig;
      ::kill(-pid, sig);
      termSent = true;
      killAt = std::min(killAt, seconds() + 5.0);
    }
    if (seconds() >= killAt) {
      if (run.stoppedBy == 0) run.timedOut = true;
      ::kill(-pid, termSent ? SIGKILL : SIGTERM);
      if (termSent) break;
      termSent = true;
      killAt = seconds() + 5.0;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(-pid, SIGKILL);  // nothing of the group outlives its leader
  int status = 0;
  rusage usage{};
  while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  run.wallSeconds = seconds();
  run.status = shellStatus(status);
  run.peakRssKb = usage.ru_maxrss;
  run.cpuSeconds = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                   1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  return run;
}

}  // namespace mpmice::coupler
