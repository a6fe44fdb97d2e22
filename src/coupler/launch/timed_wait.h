#pragma once
/// @brief Every wait of the coupler has a timeout: non-blocking MPI requests polled until done.
///
/// A wait that runs out throws CouplingTimeout naming the peer participant and what was being
/// waited for; the program's launch layer then aborts the whole launch, so no run hangs.
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
