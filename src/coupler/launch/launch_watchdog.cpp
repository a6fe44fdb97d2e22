#include "coupler/launch/launch_watchdog.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>

#include "core/util/error_line.h"

namespace mpmice::coupler {

namespace {

using Clock = std::chrono::steady_clock;

enum class Stage { StartUp, Run, Ending, Stopped };

std::atomic<Clock::rep> g_lastBeat{0};  // Clock ticks of the last progress
std::atomic<long> g_step{0};

class Watchdog {
 public:
  Watchdog(std::string program, double timeout) : program_(std::move(program)), timeout_(timeout) {
    thread_ = std::thread([this] { watch(); });
  }
  ~Watchdog() {
    set(Stage::Stopped);
    if (thread_.joinable()) thread_.join();
  }
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

  void set(Stage s) {
    {
      std::lock_guard lock(m_);
      stage_ = s;
      since_ = Clock::now();
    }
    cv_.notify_all();
  }

 private:
  void watch() {
    std::unique_lock lock(m_);
    for (;;) {
      if (stage_ == Stage::Stopped) return;
      const Stage watched = stage_;
      const auto bound = std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double>(watched == Stage::StartUp ? timeout_ : 2 * timeout_));
      // Run: measured from the last progress (or the start of the stage); else from the stage's start.
      Clock::time_point from = since_;
      if (watched == Stage::Run) from = std::max(from, Clock::time_point(Clock::duration(g_lastBeat.load())));
      const auto deadline = from + bound;
      if (Clock::now() >= deadline) {
        fire(watched);
        return;
      }
      cv_.wait_until(lock, std::min(deadline, Clock::now() + bound / 4), [&] { return stage_ != watched; });
    }
  }

  [[noreturn]] void fire(Stage s) {
    std::ostringstream os;
    if (s == Stage::StartUp)
      os << "the launch did not start within " << timeout_ << " s (coupling.timeout): the other program "
         << "of the MPMD launch did not join (it stopped or hangs during start-up)";
    else if (s == Stage::Run)
      os << "no progress for " << 2 * timeout_ << " s (twice coupling.timeout) after step " << g_step.load()
         << ": " << program_ << " hangs, or a process of the launch it waits for in a call without a timeout "
         << "stopped answering; ending the launch";
    else
      os << "the end of the run (MPI_Finalize, which waits for every process of the launch) did not complete "
         << "within " << 2 * timeout_ << " s (twice coupling.timeout): a process of the launch stopped answering; "
         << "ending the launch";
    core::writeErrorLine(program_, os.str());
    std::_Exit(1);
  }

  std::string program_;
  double timeout_;
  std::mutex m_;
  std::condition_variable cv_;
  Stage stage_ = Stage::StartUp;
  Clock::time_point since_ = Clock::now();
  std::thread thread_;
};

// The process's watchdog; destroyed (stopped) at exit, after MPI_Finalize.
std::unique_ptr<Watchdog>& instance() {
  static std::unique_ptr<Watchdog> w;
  return w;
}

void setStage(Stage s) {
  if (auto& w = instance()) w->set(s);
}

}  // namespace

namespace LaunchWatchdog {

void start(const std::string& program, double timeout) {
  g_lastBeat = Clock::now().time_since_epoch().count();
  instance() = std::make_unique<Watchdog>(program, timeout);
}
void joined() {
  beat();
  setStage(Stage::Run);
}
void ending() { setStage(Stage::Ending); }
void stop() { instance().reset(); }
void beat() noexcept { g_lastBeat.store(Clock::now().time_since_epoch().count(), std::memory_order_relaxed); }
void step(long n) noexcept {
  g_step.store(n, std::memory_order_relaxed);
  beat();
}

}  // namespace LaunchWatchdog

void maybeStallAtStart(const std::string& name) {
  const char* spec = std::getenv("MPMICE_FAULT_STALL_START");
  if (!spec) return;
  const std::string s(spec);
  const auto colon = s.find(':');
  if (colon == std::string::npos || s.substr(0, colon) != name) return;
  std::this_thread::sleep_for(std::chrono::duration<double>(std::atof(s.c_str() + colon + 1)));
}

}  // namespace mpmice::coupler
