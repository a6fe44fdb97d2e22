#pragma once
/// @brief Rank-to-rank exchange of cell-centred fields between the two participants.
///
/// Both participants decompose the same mesh (each over its own ranks). At construction every
/// rank computes, once, the overlap of its cell box with each peer rank's box. send() packs the
/// named fields over each overlap and sends one message per overlapping peer rank through the
/// inter-communicator; receive() fills the same cells of its fields. Nothing is gathered on one
/// rank. Waits are bounded by the participant's timeout.
///
/// Each tag (exchange point) gets, at its first use, its buffers and persistent requests
/// (MPI_Send_init / MPI_Recv_init), reused by every later move of that tag: a move packs, starts
/// and waits, with no allocation and no request set-up. A tag carries the same fields and
/// components every time (a different size is a logic error).
#include <map>
#include <span>
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
  ~CellExchange();
  CellExchange(const CellExchange&) = delete;
  CellExchange& operator=(const CellExchange&) = delete;

  /// Sends the owned cells of `fields` (in this order) to the peer ranks that own them there: of
  /// field i its first components[i] components (every component when `components` is empty).
  void send(const std::vector<const core::Field*>& fields, int tag, const std::string& what,
            std::span<const int> components = {});
  /// Receives into the owned cells of `fields` (same order and component counts as the sender's).
  void receive(const std::vector<core::Field*>& fields, int tag, const std::string& what,
               std::span<const int> components = {});

  /// Peer ranks this rank exchanges with (for tests and logs).
  [[nodiscard]] std::size_t numPeers() const { return overlaps_.size(); }
  /// Doubles this rank sent and received so far.
  [[nodiscard]] long long sentValues() const { return sent_; }
  [[nodiscard]] long long receivedValues() const { return received_; }

 private:
  struct Overlap {
    int peerRank;
    core::Box cells;
  };
  /// One tag's buffers (one per overlap) and persistent requests.
  struct Channel {
    bool sends = false;
    std::vector<std::vector<double>> bufs;
    std::vector<MPI_Request> reqs;
  };
  template <class FieldPtr>
  std::vector<std::size_t> messageSizes(const std::vector<FieldPtr>& fields, std::span<const int> components) const;
  Channel& channel(int tag, bool sends, const std::vector<std::size_t>& sizes, const std::string& what);
  const Participant& participant_;
  std::vector<Overlap> overlaps_;
  std::map<int, Channel> channels_;
  long long sent_ = 0, received_ = 0;
};

}  // namespace mpmice::coupler
