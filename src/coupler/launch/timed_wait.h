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

/// Waits for all requests; throws CouplingTimeout after `timeout` seconds.
void waitAll(std::vector<MPI_Request>& reqs, double timeout, const std::string& peer, const std::string& what);

}  // namespace mpmice::coupler
