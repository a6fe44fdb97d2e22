#pragma once
/// @brief Every wait of the coupler has a timeout: non-blocking MPI requests polled until done.
///
/// A wait that runs out throws CouplingTimeout naming the peer participant and what was being
/// waited for; the program's launch layer then aborts the whole launch, so no run hangs (and the
/// launch watchdog bounds everything else).
///
/// How it waits: it polls without pause while this process has its core (the latency of the
/// shared-memory transport, ~1 us, and the core is otherwise idle), checking every 16 polls
/// whether the kernel took the core away (involuntary context switches of the thread, which a
/// yield that let another task run also counts). Once it did and the core is shared (the thread
/// waited for a core more than 5 % of the wall time since the last check, the kernel's run delay:
/// more ranks than cores, builds, other tests; an idle node's brief preemptions do not count), the
/// wait polls between sleeps growing from 2 to 100 us, and the waits of the next 50 ms (renewed
/// while the core stays shared) spin only 20 us before sleeping, so a waiting rank leaves the core
/// to the peer it waits for. docs/benchmarks.md ("Coupling overhead").
#include <mpi.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace mpmice::coupler {

class CouplingTimeout : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What a wait is for: data from the peer, or the peer taking what this side sends.
enum class Waiting { ForData, ForReceipt };

/// The timeout message: "coupler: no <what> from participant '<peer>' within ..." when waiting for
/// data, "coupler: <what> sent, but no receipt from participant '<peer>' within ..." when sending.
std::string timeoutMessage(const std::string& peer, const std::string& what, double timeout, Waiting waiting);

/// Waits for all requests; throws CouplingTimeout (timeoutMessage) after `timeout` seconds.
void waitAll(std::vector<MPI_Request>& reqs, double timeout, const std::string& peer, const std::string& what,
             Waiting waiting = Waiting::ForData);

}  // namespace mpmice::coupler
