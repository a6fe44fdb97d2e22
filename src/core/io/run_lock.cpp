#include "core/io/run_lock.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <utility>
#include <unistd.h>

#include "core/io/text_file.h"

namespace mpmice::core {

namespace fs = std::filesystem;

namespace {

std::string hostName() {
  char buf[256] = {};
  if (gethostname(buf, sizeof buf - 1) != 0) return "unknown";
  return buf;
}

struct Holder {
  long pid = 0;
  std::string host, program;
  [[nodiscard]] bool ok() const { return pid > 0 && !host.empty(); }
};

Holder parse(const std::string& text) {
  Holder h;
  std::istringstream is(text);
  is >> h.pid >> h.host >> h.program;
  if (!is && !is.eof()) h.pid = 0;
  return h;
}

/// State and parent of `pid` from /proc/<pid>/stat ({0, 0} when unknown).
std::pair<char, long> stateAndParent(long pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto close = all.rfind(')');  // the command name may hold spaces
  if (close == std::string::npos) return {0, 0};
  std::istringstream is(all.substr(close + 1));
  char state = 0;
  long ppid = 0;
  is >> state >> ppid;
  return {state, ppid};
}

long parentOf(long pid) { return stateAndParent(pid).second; }

/// Alive: it exists and has not ended (a zombie, ended but not yet reaped, is dead).
bool alive(long pid) {
  if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno != EPERM) return false;
  const char state = stateAndParent(pid).first;
  return state != 'Z' && state != 'X';
}

/// Whether `pid` is this process or one of its ancestors.
bool selfOrAncestor(long pid) {
  for (long p = getpid(); p > 1; p = parentOf(p))
    if (p == pid) return true;
  return false;
}

/// Whether a lock's holder is a live process (a holder on another host counts as live).
bool holderLive(const Holder& h) { return h.ok() && (h.host != hostName() || alive(h.pid)); }

std::string refusal(const std::string& path, const std::string& held) {
  return "the output directory is in use: " + path + " is held by " + RunLock::describeHolder(held) +
         "; wait for that run to end, stop it, or set output.directory to another folder (a lock whose process has "
         "ended is taken over)";
}

}  // namespace

std::string RunLock::describeHolder(const std::string& lockText) {
  const Holder h = parse(lockText);
  if (!h.ok()) return {};
  return "pid " + std::to_string(h.pid) + " on host " + h.host + (h.program.empty() ? "" : " (" + h.program + ")");
}

RunLock::RunLock(const std::string& directory, const std::string& name, const std::string& program,
                 const std::vector<std::string>& conflicts, std::ostream* log) {
  std::error_code ec;
  fs::create_directories(directory, ec);
  path_ = (fs::path(directory) / (name + ".lock")).string();
  text_ = std::to_string(getpid()) + " " + hostName() + " " + program + "\n";
  for (const auto& other : conflicts) {
    const std::string p = (fs::path(directory) / (other + ".lock")).string();
    const std::string held = readTextFile(p);
    const Holder h = parse(held);
    if (holderLive(h) && !(h.host == hostName() && selfOrAncestor(h.pid))) throw RunLockHeld(refusal(p, held));
  }
  for (int attempt = 0; attempt < 3; ++attempt) {
    const int fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd >= 0) {
      const bool written = ::write(fd, text_.data(), text_.size()) == static_cast<ssize_t>(text_.size());
      ::close(fd);
      if (!written) throw std::runtime_error("cannot write the lock " + path_);
      return;
    }
    if (errno != EEXIST) throw std::runtime_error("cannot create the lock " + path_ + ": " + std::strerror(errno));
    const std::string held = readTextFile(path_);
    const Holder h = parse(held);
    if (!h.ok()) {
      // Being written this instant, or a broken file: look again, then treat it as stale.
      if (attempt == 0) {
        ::usleep(100000);
        continue;
      }
    } else if (holderLive(h)) {
      throw RunLockHeld(refusal(path_, held));
    }
    if (log)
      *log << "note: taking over the stale lock " << path_
           << (h.ok() ? " of " + describeHolder(held) + ", which is no longer running" : std::string(" (unreadable)"))
           << "\n"
           << std::flush;
    fs::remove(path_, ec);
  }
  throw std::runtime_error("cannot take the lock " + path_ + ": it keeps reappearing");
}

RunLock::~RunLock() {
  if (readTextFile(path_) == text_) {
    std::error_code ec;
    fs::remove(path_, ec);
  }
}

std::unique_ptr<RunLock> RunLock::acquire(const Comm& comm, const std::string& directory, const std::string& name,
                                          const std::string& program, const std::vector<std::string>& conflicts,
                                          std::ostream* log) {
  std::unique_ptr<RunLock> lock;
  int failure = 0;  // 0 taken, 1 held, 2 other error
  std::string message;
  if (comm.root()) {
    try {
      lock = std::make_unique<RunLock>(directory, name, program, conflicts, log);
    } catch (const RunLockHeld& e) {
      failure = 1;
      message = e.what();
    } catch (const std::exception& e) {
      failure = 2;
      message = e.what();
    }
  }
  if (comm.size() > 1) {
    MPI_Bcast(&failure, 1, MPI_INT, 0, comm.raw());
    int n = static_cast<int>(message.size());
    MPI_Bcast(&n, 1, MPI_INT, 0, comm.raw());
    message.resize(static_cast<std::size_t>(n));
    MPI_Bcast(message.data(), n, MPI_CHAR, 0, comm.raw());
  }
  if (failure == 1) throw RunLockHeld(message);
  if (failure == 2) throw std::runtime_error(message);
  return lock;
}

std::unique_ptr<RunLock> lockOutputDirectory(const Comm& comm, const Scene& scene, const std::string& program,
                                             std::ostream* log) {
  if (!scene.output.enabled) return nullptr;
  const std::string& dir = scene.output.directory;
  if (program == "coupler" || program == "mpmice")
    return RunLock::acquire(comm, dir, scene.name, program, {scene.name + ".mpm_solver", scene.name + ".ice_solver"}, log);
  return RunLock::acquire(comm, dir, scene.name + "." + program, program, {scene.name}, log);
}

}  // namespace mpmice::core
