#include "coupler/transport/mpi_transport.h"

#include <stdexcept>

#include "coupler/launch/timed_wait.h"
#include "coupler/transport/stopwatch.h"

namespace mpmice::coupler {

namespace {
constexpr int kTradeTag = 31;
}  // namespace

std::vector<double> tradeValues(const Participant& p, const std::vector<double>& mine, const std::string& what) {
  std::vector<double> theirs(mine.size(), 0.0);
  if (p.local().root()) {
    std::vector<MPI_Request> reqs(2);
    const int n = static_cast<int>(mine.size());
    MPI_Irecv(theirs.data(), n, MPI_DOUBLE, 0, kTradeTag, p.inter(), &reqs[0]);
    MPI_Isend(mine.data(), n, MPI_DOUBLE, 0, kTradeTag, p.inter(), &reqs[1]);
    waitAll(reqs, p.timeout(), p.peerName(), what);
  }
  MPI_Bcast(theirs.data(), static_cast<int>(theirs.size()), MPI_DOUBLE, 0, p.local().raw());
  return theirs;
}

MpiTransport::MpiTransport(const Participant& participant, const core::Decomposition& mine,
                           const core::Decomposition& peer)
    : participant_(participant), exchange_(participant, mine, peer) {}

void MpiTransport::move(std::span<const core::Field* const> from, std::span<core::Field* const> to, int tag,
                        const std::string& what) {
  const Stopwatch watch(seconds_);
  if (!from.empty() && !to.empty())
    throw std::logic_error("MPI transport: " + what + " is produced and consumed in one process");
  ++moves_;
  if (!from.empty()) exchange_.send({from.begin(), from.end()}, tag, what);
  if (!to.empty()) exchange_.receive({to.begin(), to.end()}, tag, what);
}

std::vector<double> MpiTransport::trade(const std::vector<double>& mine, const std::string& what) {
  const Stopwatch watch(seconds_);
  ++trades_;
  return tradeValues(participant_, mine, what);
}

}  // namespace mpmice::coupler
