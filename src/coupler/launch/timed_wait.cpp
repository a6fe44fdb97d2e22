#include "coupler/launch/timed_wait.h"

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

void waitAll(std::vector<MPI_Request>& reqs, double timeout, const std::string& peer, const std::string& what,
             Waiting waiting) {
  if (reqs.empty()) return;
  const auto start = std::chrono::steady_clock::now();
  int spins = 0;
  for (;;) {
    int done = 0;
    MPI_Testall(static_cast<int>(reqs.size()), reqs.data(), &done, MPI_STATUSES_IGNORE);
    LaunchWatchdog::beat();  // waiting within a bound is progress (the bound names the peer)
    if (done) return;
    const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (waited > timeout) {
      for (auto& r : reqs)
        if (r != MPI_REQUEST_NULL) {
          MPI_Cancel(&r);
          MPI_Request_free(&r);
        }
      throw CouplingTimeout(timeoutMessage(peer, what, timeout, waiting));
    }
    // Spin briefly for low latency, then sleep between polls. Polling with yield() instead was
    // 1.5x faster on an idle machine but 3-4x slower with the 2 cores oversubscribed (other
    // ranks, builds, parallel tests): docs/benchmarks.md.
    if (++spins > 200) std::this_thread::sleep_for(std::chrono::microseconds(spins > 2000 ? 500 : 20));
  }
}

}  // namespace mpmice::coupler
