#include "coupler/launch/timed_wait.h"

#include <sys/prctl.h>
#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
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

// Time the calling thread spent runnable but waiting for a core, in ns (the second field of
// /proc/thread-self/schedstat), or -1 where the kernel does not report it.
long long runDelayNs() {
  std::FILE* f = std::fopen("/proc/thread-self/schedstat", "r");
  if (!f) return -1;
  unsigned long long cpu = 0, delay = 0;
  const int n = std::fscanf(f, "%llu %llu", &cpu, &delay);
  std::fclose(f);
  return n == 2 ? static_cast<long long>(delay) : -1;
}

// Whether the core is really shared, asked when a poll lost its core. An idle node preempts a
// spinning rank now and then for a few microseconds (kernel threads, the launcher): that is no
// reason to sleep, and sleeping there costs every later exchange its wake-up. So the time the
// thread waited for a core since the last question is compared with the wall time since then:
// above 5 % the core is shared (oversubscribed cores give 30 % and more; an idle one below 1 %).
// Without the kernel's figure every lost core counts as shared.
bool coreIsShared(Clock::time_point now) {
  static long long lastDelay = runDelayNs();
  static Clock::time_point lastTime = now;
  const long long delay = runDelayNs();
  if (delay < 0 || lastDelay < 0) return true;
  const double waited = 1e-9 * static_cast<double>(delay - lastDelay);
  const double wall = std::chrono::duration<double>(now - lastTime).count();
  lastDelay = delay;
  lastTime = now;
  return waited > 0.05 * wall;
}

// Until when the waits of this process start by sleeping: set when a poll lost its core.
std::atomic<Clock::rep> g_contendedUntil{0};
constexpr auto kContendedFor = std::chrono::milliseconds(50);
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
  // otherwise idle. Once the kernel takes the core away while polling and the core is shared
  // (other ranks or programs want it: coreIsShared), poll with sleeps that grow to 100 us, and
  // start the waits of the next 50 ms so; renewed while the core stays shared.
  bool contended = false;
  if (const auto until = g_contendedUntil.load(std::memory_order_relaxed); until != 0) {
    contended = start.time_since_epoch().count() < until;
    if (!contended) {  // the sleeping period ended: keep sleeping only while the core stays shared
      contended = coreIsShared(start);
      g_contendedUntil.store(contended ? (start + kContendedFor).time_since_epoch().count() : 0,
                             std::memory_order_relaxed);
    }
  }
  auto spinUntil = contended ? start + kSpinWhenContended : deadline;
  long switches0 = involuntarySwitches();
  auto nap = std::chrono::microseconds(2);
  for (int polls = 1;; ++polls) {
    int done = 0;
    MPI_Testall(static_cast<int>(reqs.size()), reqs.data(), &done, MPI_STATUSES_IGNORE);
    if (done) break;
    const auto now = Clock::now();
    if (now < spinUntil) {
      if (polls % kPollsPerCheck == 0) {
        const long switches = involuntarySwitches();
        if (switches != switches0) {
          switches0 = switches;
          if (coreIsShared(now)) {  // lost the core to a task that wants it: sleep from now on
            spinUntil = now;
            g_contendedUntil.store((now + kContendedFor).time_since_epoch().count(), std::memory_order_relaxed);
          }
        }
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
