#pragma once
/// @brief Transport rank to rank between the two programs of an MPMD launch.
///
/// move() sends the owned cells of the producer's fields to the peer ranks that own them there
/// (this process produces), or receives them (it consumes), through CellExchange; trade() swaps
/// a few scalars between the leaders and broadcasts the peer's values to every local rank.
/// Every wait is bounded by the participant's timeout and names the peer and the data.
#include "coupler/exchange/cell_exchange.h"
#include "coupler/launch/participant.h"
#include "coupler/transport/transport.h"

namespace mpmice::coupler {

/// Leaders trade `mine` (same length on both sides); every local rank gets the peer's values.
std::vector<double> tradeValues(const Participant& p, const std::vector<double>& mine, const std::string& what);

class MpiTransport final : public Transport {
 public:
  /// mine: this program's decomposition; the peer's is built from the same mesh.
  MpiTransport(const Participant& participant, const core::Decomposition& mine, const core::Decomposition& peer);
  void move(std::span<const core::Field* const> from, std::span<core::Field* const> to,
            std::span<const int> components, int tag, const std::string& what) override;
  std::vector<double> trade(const std::vector<double>& mine, const std::string& what) override;
  double measureLatency(int rounds) override;
  [[nodiscard]] bool inMemory() const override { return false; }
  [[nodiscard]] const Participant& participant() const { return participant_; }

 private:
  const Participant& participant_;
  CellExchange exchange_;
};

}  // namespace mpmice::coupler
