#include "core/parallel/ghost_exchange.h"

#include <algorithm>
#include <stdexcept>

namespace mpmice::core {

namespace {

/// Periodic image shifts (in index units) for the directions that wrap.
std::vector<IntVect> imageShifts(const Decomposition& d, Centering c) {
  std::vector<IntVect> shifts;
  const IntVect per = d.period(c);
  const int dim = d.mesh().dim();
  for (int sz = -1; sz <= 1; ++sz)
    for (int sy = -1; sy <= 1; ++sy)
      for (int sx = -1; sx <= 1; ++sx) {
        const int s[3] = {sx, sy, sz};
        bool ok = true;
        for (int e = 0; e < 3; ++e)
          if (s[e] != 0 && (e >= dim || !d.periodic()[e])) ok = false;
        if (ok) shifts.push_back({sx * per[0], sy * per[1], sz * per[2]});
      }
  return shifts;
}

/// Rank r's owned box, extended by ng beyond the non-periodic domain faces it touches.
Box ownedWithExterior(const Decomposition& d, int r, Centering c, int ng) {
  Box b = d.ownedBox(r, c);
  const Box cells = d.cellBox(r);
  for (int dir = 0; dir < d.mesh().dim(); ++dir) {
    if (d.periodic()[dir]) continue;
    if (cells.lo[dir] == 0) b = b.growLo(dir, ng);
    if (cells.hi[dir] == d.mesh().cells()[dir] - 1) b = b.growHi(dir, ng);
  }
  return b;
}

}  // namespace

GhostExchange::GhostExchange(const Decomposition& decomp, const Comm& comm, Centering c, int nghost,
                             bool ownExterior)
    : comm_(comm) {
  if (decomp.numRanks() != comm.size())
    throw std::invalid_argument("GhostExchange: decomposition has " + std::to_string(decomp.numRanks()) +
                                " boxes but the communicator has " + std::to_string(comm.size()) + " ranks");
  const int me = comm.rank();
  stored_ = decomp.storedBox(me, c, nghost);
  auto owned = [&](int r) { return ownExterior ? ownedWithExterior(decomp, r, c, nghost) : decomp.ownedBox(r, c); };
  owned_ = owned(me);
  const auto shifts = imageShifts(decomp, c);
  for (int peer = 0; peer < decomp.numRanks(); ++peer) {
    const Box peerOwned = owned(peer);
    const Box peerStored = decomp.storedBox(peer, c, nghost);
    for (const IntVect& s : shifts) {
      const bool self = (peer == me && s == IntVect{0, 0, 0});
      if (self) continue;
      // My stored region overlapping the peer's owned region seen through image shift s.
      Box mine = stored_ & peerOwned.shift(s);
      if (mine.ok()) recvFrom_.push_back({peer, mine, mine.shift({-s[0], -s[1], -s[2]})});
      // The peer's stored region overlapping my owned region seen through image shift s.
      Box theirs = peerStored & owned_.shift(s);
      if (theirs.ok()) sendTo_.push_back({peer, theirs.shift({-s[0], -s[1], -s[2]}), theirs});
    }
  }
}

void GhostExchange::fill(Field& f) const { exchange({&f}, false); }
void GhostExchange::sumAndFill(Field& f) const { sumAndFill(std::vector<Field*>{&f}); }
void GhostExchange::fill(const std::vector<Field*>& fs) const { exchange(fs, false); }
void GhostExchange::sumAndFill(const std::vector<Field*>& fs) const {
  exchange(fs, true);
  exchange(fs, false);
}

// Forward (fill): send my owned overlaps, receive into my ghosts (copy).
// Reverse (sum): send my ghost overlaps, receive into my owned (add).
// Messages to one peer concatenate all its overlaps in a fixed order, so each pair exchanges
// exactly one message per direction.
void GhostExchange::exchange(const std::vector<Field*>& fs, bool reverseAdd) const {
  for (Field* f : fs)
    if (!(f->box() == stored_))
      throw std::invalid_argument("GhostExchange: field '" + f->name() + "' is stored over " +
                                  f->box().str() + ", the exchange expects " + stored_.str());
  const auto& outList = reverseAdd ? recvFrom_ : sendTo_;
  const auto& inList = reverseAdd ? sendTo_ : recvFrom_;
  const int tag = reverseAdd ? 7102 : 7101;
  const int nranks = comm_.size();

  std::vector<std::vector<double>> sendBuf(nranks), recvBuf(nranks);
  for (const auto& o : outList)
    for (const Field* f : fs) f->pack(o.mine, sendBuf[o.peer]);
  std::vector<std::size_t> recvSize(nranks, 0);
  for (const auto& o : inList)
    for (const Field* f : fs) recvSize[o.peer] += static_cast<std::size_t>(o.mine.numPts() * f->ncomp());

  std::vector<MPI_Request> reqs;
  for (int p = 0; p < nranks; ++p) {
    if (p == comm_.rank() || recvSize[p] == 0) continue;
    recvBuf[p].resize(recvSize[p]);
    reqs.emplace_back();
    MPI_Irecv(recvBuf[p].data(), static_cast<int>(recvSize[p]), MPI_DOUBLE, p, tag, comm_.raw(), &reqs.back());
  }
  for (int p = 0; p < nranks; ++p) {
    if (p == comm_.rank() || sendBuf[p].empty()) continue;
    reqs.emplace_back();
    MPI_Isend(sendBuf[p].data(), static_cast<int>(sendBuf[p].size()), MPI_DOUBLE, p, tag, comm_.raw(),
              &reqs.back());
  }
  // Self images (periodic wrap onto my own box) need no message.
  recvBuf[comm_.rank()] = std::move(sendBuf[comm_.rank()]);
  MPI_Waitall(static_cast<int>(reqs.size()), reqs.data(), MPI_STATUSES_IGNORE);

  // inList and the peer's outList enumerate the same overlaps in the same order (peer-major,
  // shift-minor on both sides), so the offsets line up.
  std::vector<std::size_t> offset(nranks, 0);
  for (const auto& o : inList)
    for (Field* f : fs) offset[o.peer] += f->unpack(o.mine, recvBuf[o.peer].data() + offset[o.peer], reverseAdd);
}

}  // namespace mpmice::core
