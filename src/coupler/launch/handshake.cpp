#include "coupler/launch/handshake.h"

#include <map>
#include <sstream>

#include "coupler/launch/timed_wait.h"

namespace mpmice::coupler {

std::string tradeWithPeer(const Participant& p, const std::string& mine, const std::string& what) {
  long long sizes[2] = {static_cast<long long>(mine.size()), 0};
  std::string theirs;
  if (p.local().root()) {
    std::vector<MPI_Request> reqs(2);
    MPI_Irecv(&sizes[1], 1, MPI_LONG_LONG, 0, 11, p.inter(), &reqs[0]);
    MPI_Isend(&sizes[0], 1, MPI_LONG_LONG, 0, 11, p.inter(), &reqs[1]);
    waitAll(reqs, p.timeout(), p.peerName(), what);
    theirs.resize(static_cast<std::size_t>(sizes[1]));
    MPI_Irecv(theirs.data(), static_cast<int>(sizes[1]), MPI_CHAR, 0, 12, p.inter(), &reqs[0]);
    MPI_Isend(mine.data(), static_cast<int>(sizes[0]), MPI_CHAR, 0, 12, p.inter(), &reqs[1]);
    waitAll(reqs, p.timeout(), p.peerName(), what);
  }
  MPI_Bcast(&sizes[1], 1, MPI_LONG_LONG, 0, p.local().raw());
  theirs.resize(static_cast<std::size_t>(sizes[1]));
  MPI_Bcast(theirs.data(), static_cast<int>(sizes[1]), MPI_CHAR, 0, p.local().raw());
  return theirs;
}

namespace {
constexpr char kUnit = '\x1f', kRecord = '\x1e';

std::string encode(const HandshakeSections& s) {
  std::string out;
  for (const auto& [k, v] : s) out += k + kUnit + v + kRecord;
  return out;
}

HandshakeSections decode(const std::string& text) {
  HandshakeSections s;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t u = text.find(kUnit, pos), r = text.find(kRecord, pos);
    if (u == std::string::npos || r == std::string::npos || u > r) break;
    s.emplace_back(text.substr(pos, u - pos), text.substr(u + 1, r - u - 1));
    pos = r + 1;
  }
  return s;
}
}  // namespace

HandshakeSections handshake(const Participant& p, const HandshakeSections& mine) {
  const HandshakeSections theirs = decode(tradeWithPeer(p, encode(mine), "handshake"));
  std::map<std::string, std::string> t(theirs.begin(), theirs.end());
  std::ostringstream diff;
  for (const auto& [k, v] : mine) {
    auto it = t.find(k);
    if (it == t.end()) continue;  // a section only one side describes is not compared
    if (it->second != v)
      diff << "\n  " << k << " differs:\n    " << p.name() << ": " << v << "\n    " << p.peerName() << ": "
           << it->second;
  }
  if (!diff.str().empty())
    throw HandshakeMismatch("coupler: participant '" + p.name() + "' and participant '" + p.peerName() +
                            "' did not read the same scene:" + diff.str() +
                            "\n  start both programs with the same scene file");
  return theirs;
}

}  // namespace mpmice::coupler
