#pragma once
/// @brief Rank-to-rank exchange of cell-centred fields between the two participants.
///
/// Both participants decompose the same mesh (each over its own ranks). At construction every
/// rank computes, once, the overlap of its cell box with each peer rank's box. send() packs the
/// named fields over each overlap and sends one message per overlapping peer rank through the
/// inter-communicator; receive() fills the same cells of its fields. Nothing is gathered on one
/// rank. Waits are bounded by the participant's timeout.
#include <string>
#include <vector>

#include "core/field/field.h"
#include "coupler/launch/participant.h"
#include "core/parallel/decomposition.h"

namespace mpmice::coupler {

class CellExchange {
 public:
  /// mine: this program's decomposition (its communicator's size); peer: the peer's, built from the
  /// same mesh over participant.peerSize() ranks.
  CellExchange(const Participant& participant, const core::Decomposition& mine, const core::Decomposition& peer);

  /// Sends the owned cells of `fields` (in this order) to the peer ranks that own them there.
  void send(const std::vector<const core::Field*>& fields, int tag, const std::string& what) const;
  /// Receives into the owned cells of `fields` (same order and component counts as the sender's).
  void receive(const std::vector<core::Field*>& fields, int tag, const std::string& what) const;

  /// Peer ranks this rank exchanges with (for tests and logs).
  [[nodiscard]] std::size_t numPeers() const { return overlaps_.size(); }
  /// Doubles this rank sent and received so far.
  [[nodiscard]] long long sentValues() const { return sent_; }

 private:
  struct Overlap {
    int peerRank;
    core::Box cells;
  };
  const Participant& participant_;
  std::vector<Overlap> overlaps_;
  mutable long long sent_ = 0;
};

}  // namespace mpmice::coupler
