#include "coupler/exchange/cell_exchange.h"

#include <stdexcept>

#include "coupler/launch/timed_wait.h"

namespace mpmice::coupler {

CellExchange::CellExchange(const Participant& participant, const core::Decomposition& mine,
                           const core::Decomposition& peer)
    : participant_(participant) {
  if (!participant.coupled()) throw std::logic_error("CellExchange: participant is not coupled");
  if (!(mine.mesh() == peer.mesh()))
    throw std::logic_error("CellExchange: the two decompositions are of different meshes");
  const core::Box myCells = mine.cellBox(participant.local().rank());
  for (int s = 0; s < peer.numRanks(); ++s) {
    const core::Box o = myCells & peer.cellBox(s);
    if (o.ok()) overlaps_.push_back({s, o});
  }
}

void CellExchange::send(const std::vector<const core::Field*>& fields, int tag, const std::string& what) const {
  std::vector<std::vector<double>> bufs(overlaps_.size());
  std::vector<MPI_Request> reqs(overlaps_.size());
  for (std::size_t n = 0; n < overlaps_.size(); ++n) {
    for (const core::Field* f : fields) f->pack(overlaps_[n].cells, bufs[n]);
    sent_ += static_cast<long long>(bufs[n].size());
    MPI_Isend(bufs[n].data(), static_cast<int>(bufs[n].size()), MPI_DOUBLE, overlaps_[n].peerRank, tag,
              participant_.inter(), &reqs[n]);
  }
  waitAll(reqs, participant_.timeout(), participant_.peerName(), what, Waiting::ForReceipt);
}

void CellExchange::receive(const std::vector<core::Field*>& fields, int tag, const std::string& what) const {
  std::vector<std::vector<double>> bufs(overlaps_.size());
  std::vector<MPI_Request> reqs(overlaps_.size());
  for (std::size_t n = 0; n < overlaps_.size(); ++n) {
    std::size_t size = 0;
    for (const core::Field* f : fields) size += static_cast<std::size_t>(overlaps_[n].cells.numPts() * f->ncomp());
    bufs[n].resize(size);
    MPI_Irecv(bufs[n].data(), static_cast<int>(size), MPI_DOUBLE, overlaps_[n].peerRank, tag,
              participant_.inter(), &reqs[n]);
  }
  waitAll(reqs, participant_.timeout(), participant_.peerName(), what);
  for (std::size_t n = 0; n < overlaps_.size(); ++n) {
    std::size_t off = 0;
    for (core::Field* f : fields) off += f->unpack(overlaps_[n].cells, bufs[n].data() + off, false);
  }
}

}  // namespace mpmice::coupler
