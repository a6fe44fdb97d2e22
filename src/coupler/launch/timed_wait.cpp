#include "coupler/launch/timed_wait.h"

#include <sys/prctl.h>
#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <sstream>
#include <thread>

#include "coupler/launch/launch_watchdog.h"

namespace mpmice::coupler {

std::string timeoutMessage(const std::string& peer, const std::string& what, double timeout, Waiting waiting) {
  std::ostringstream os;
  if (waiting == Waiting::ForReceipt) os << "coupler: " << what << " sent, but no receipt";
  else os << "coupler: no " << what;
  os << " from participant '" << peer << "'";
  os << " within " << timeout << " s (coupling.timeout); it has stopped or hangs";
  return os.str();
}

namespace {

using Clock = std::chrono::steady_clock;

// Involuntary context switches of the calling thread: the kernel gave its core to another task
// while it polled (a sched_yield that switched counts too). None while a rank has a core to
// itself; some as soon as the cores are oversubscribed.
long involuntarySwitches() {
  rusage u{};
  getrusage(RUSAGE_THREAD, &u);
  return u.ru_nivcsw;
}

// Until when the waits of this process start by sleeping: set when a poll lost its core.
std::atomic<Clock::rep> g_contendedUntil{0};
constexpr auto kContendedFor = std::chrono::milliseconds(200);
constexpr auto kSpinWhenContended = std::chrono::microseconds(20);
constexpr auto kLongestSleep = std::chrono::microseconds(100);
constexpr int kPollsPerCheck = 16;

// Sleeps as short as asked: the default timer slack (50 us) would stretch every short sleep.
void shortTimerSlack() {
  static const bool once = [] {
    prctl(PR_SET_TIMERSLACK, 1000UL, 0, 0, 0);  // 1 us, this thread (the main thread does every wait)
    return true;
  }();
  (void)once;
}

}  // namespace

void waitAll(std::vector<MPI_Request>& reqs, double timeout, const std::string& peer, const std::string& what,
             Waiting waiting) {
  if (reqs.empty()) return;
  shortTimerSlack();
  const auto start = Clock::now();
  const auto deadline = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout));
  // Spin (poll without pause) while this rank has its core: the lowest latency, and the core is
  // otherwise idle. Once the kernel takes the core away while polling (other ranks or programs
  // want it), poll with sleeps that grow to 100 us, and start the waits of the next 200 ms so.
  const bool contended = Clock::now().time_since_epoch().count() < g_contendedUntil.load(std::memory_order_relaxed);
  auto spinUntil = contended ? start + kSpinWhenContended : deadline;
  const long switches0 = involuntarySwitches();
  auto nap = std::chrono::microseconds(2);
  for (int polls = 1;; ++polls) {
    int done = 0;
    MPI_Testall(static_cast<int>(reqs.size()), reqs.data(), &done, MPI_STATUSES_IGNORE);
    if (done) break;
    const auto now = Clock::now();
    if (now < spinUntil) {
      if (polls % kPollsPerCheck == 0 && involuntarySwitches() != switches0) {
        spinUntil = now;  // lost the core while spinning: sleep from now on
        g_contendedUntil.store((now + kContendedFor).time_since_epoch().count(), std::memory_order_relaxed);
      }
      continue;
    }
    LaunchWatchdog::beat();  // waiting within a bound is progress (the bound names the peer)
    if (now > deadline) {
      for (auto& r : reqs)
        if (r != MPI_REQUEST_NULL) {
          MPI_Cancel(&r);
          MPI_Request_free(&r);
        }
      throw CouplingTimeout(timeoutMessage(peer, what, timeout, waiting));
    }
    std::this_thread::sleep_for(nap);
    nap = std::min(nap * 2, kLongestSleep);
  }
  LaunchWatchdog::beat();
}

}  // namespace mpmice::coupler
