#include "coupler/transport/mpi_transport.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "coupler/launch/timed_wait.h"
#include "coupler/transport/stopwatch.h"

namespace mpmice::coupler {

namespace {
constexpr int kTradeTag = 31, kLatencyTag = 32;
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

void MpiTransport::move(std::span<const core::Field* const> from, std::span<core::Field* const> to,
                        std::span<const int> components, int tag, const std::string& what) {
  double seconds = 0;
  const long long before = exchange_.sentValues() + exchange_.receivedValues();
  {
    const Stopwatch total(seconds_), point(seconds);
    if (!from.empty() && !to.empty())
      throw std::logic_error("MPI transport: " + what + " is produced and consumed in one process");
    if (components.size() != std::max(from.size(), to.size()))
      throw std::logic_error("MPI transport: " + what + ": components not declared for every field");
    ++moves_;
    if (!from.empty()) exchange_.send({from.begin(), from.end()}, tag, what, components);
    if (!to.empty()) exchange_.receive({to.begin(), to.end()}, tag, what, components);
  }
  const long long values = exchange_.sentValues() + exchange_.receivedValues() - before;
  account(tag, what, seconds, static_cast<long long>(sizeof(double)) * values);
}

std::vector<double> MpiTransport::trade(const std::vector<double>& mine, const std::string& what) {
  const Stopwatch watch(seconds_);
  ++trades_;
  return tradeValues(participant_, mine, what);
}

double MpiTransport::measureLatency(int rounds) {
  if (!participant_.local().root() || rounds < 1) return 0.0;
  double mine = 0, theirs = 0;
  std::vector<MPI_Request> reqs(2, MPI_REQUEST_NULL);
  MPI_Recv_init(&theirs, 1, MPI_DOUBLE, 0, kLatencyTag, participant_.inter(), &reqs[0]);
  MPI_Send_init(&mine, 1, MPI_DOUBLE, 0, kLatencyTag, participant_.inter(), &reqs[1]);
  std::vector<double> times;
  for (int r = 0; r <= rounds; ++r) {  // round 0 waits for the peer to arrive: not counted
    const auto start = std::chrono::steady_clock::now();
    MPI_Startall(2, reqs.data());
    waitAll(reqs, participant_.timeout(), participant_.peerName(), "latency probe");
    if (r > 0) times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  for (auto& q : reqs) MPI_Request_free(&q);
  std::nth_element(times.begin(), times.begin() + static_cast<std::ptrdiff_t>(times.size() / 2), times.end());
  return times[times.size() / 2];
}

}  // namespace mpmice::coupler
