#include "coupler/exchange/cell_exchange.h"

#include <stdexcept>

#include "coupler/launch/timed_wait.h"

namespace mpmice::coupler {

namespace {
int componentsOf(const core::Field& f, std::span<const int> components, std::size_t i) {
  return components.empty() ? f.ncomp() : components[i];
}
}  // namespace

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

CellExchange::~CellExchange() {
  for (auto& [tag, c] : channels_)
    for (auto& r : c.reqs)
      if (r != MPI_REQUEST_NULL) MPI_Request_free(&r);  // inactive persistent requests
}

template <class FieldPtr>
std::vector<std::size_t> CellExchange::messageSizes(const std::vector<FieldPtr>& fields,
                                                    std::span<const int> components) const {
  std::vector<std::size_t> sizes(overlaps_.size(), 0);
  for (std::size_t n = 0; n < overlaps_.size(); ++n)
    for (std::size_t i = 0; i < fields.size(); ++i)
      sizes[n] += static_cast<std::size_t>(overlaps_[n].cells.numPts() * componentsOf(*fields[i], components, i));
  return sizes;
}

CellExchange::Channel& CellExchange::channel(int tag, bool sends, const std::vector<std::size_t>& sizes,
                                             const std::string& what) {
  auto it = channels_.find(tag);
  if (it != channels_.end()) {
    Channel& c = it->second;
    bool same = c.sends == sends;
    for (std::size_t n = 0; same && n < sizes.size(); ++n) same = c.bufs[n].size() == sizes[n];
    for (const auto& r : c.reqs) same = same && r != MPI_REQUEST_NULL;  // freed by a timed-out wait
    if (!same) throw std::logic_error("CellExchange: " + what + " (tag " + std::to_string(tag) +
                                      ") changed its direction or size since its first move");
    return c;
  }
  Channel& c = channels_[tag];
  c.sends = sends;
  c.bufs.resize(overlaps_.size());
  c.reqs.assign(overlaps_.size(), MPI_REQUEST_NULL);
  for (std::size_t n = 0; n < overlaps_.size(); ++n) {
    c.bufs[n].resize(sizes[n]);
    const int count = static_cast<int>(sizes[n]);
    if (sends)
      MPI_Send_init(c.bufs[n].data(), count, MPI_DOUBLE, overlaps_[n].peerRank, tag, participant_.inter(), &c.reqs[n]);
    else
      MPI_Recv_init(c.bufs[n].data(), count, MPI_DOUBLE, overlaps_[n].peerRank, tag, participant_.inter(), &c.reqs[n]);
  }
  return c;
}

void CellExchange::send(const std::vector<const core::Field*>& fields, int tag, const std::string& what,
                        std::span<const int> components) {
  Channel& c = channel(tag, true, messageSizes(fields, components), what);
  for (std::size_t n = 0; n < overlaps_.size(); ++n) {
    double* out = c.bufs[n].data();
    for (std::size_t i = 0; i < fields.size(); ++i)
      for (int k = 0; k < componentsOf(*fields[i], components, i); ++k) {
        const auto v = fields[i]->view(k);
        core::forEach(overlaps_[n].cells, [&](int a, int b, int z) { *out++ = v(a, b, z); });
      }
    sent_ += static_cast<long long>(c.bufs[n].size());
  }
  MPI_Startall(static_cast<int>(c.reqs.size()), c.reqs.data());
  waitAll(c.reqs, participant_.timeout(), participant_.peerName(), what, Waiting::ForReceipt);
}

void CellExchange::receive(const std::vector<core::Field*>& fields, int tag, const std::string& what,
                           std::span<const int> components) {
  Channel& c = channel(tag, false, messageSizes(fields, components), what);
  MPI_Startall(static_cast<int>(c.reqs.size()), c.reqs.data());
  waitAll(c.reqs, participant_.timeout(), participant_.peerName(), what);
  for (std::size_t n = 0; n < overlaps_.size(); ++n) {
    const double* in = c.bufs[n].data();
    for (std::size_t i = 0; i < fields.size(); ++i)
      for (int k = 0; k < componentsOf(*fields[i], components, i); ++k) {
        auto v = fields[i]->view(k);
        core::forEach(overlaps_[n].cells, [&](int a, int b, int z) { v(a, b, z) = *in++; });
      }
    received_ += static_cast<long long>(c.bufs[n].size());
  }
}

}  // namespace mpmice::coupler
