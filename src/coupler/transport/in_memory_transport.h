#pragma once
/// @brief Transport between two sides in one process: move() copies the owned cells of each
/// producer field into the consumer's; trade() returns its argument (the peer is this process).
#include "coupler/transport/transport.h"

namespace mpmice::coupler {

class InMemoryTransport final : public Transport {
 public:
  void move(std::span<const core::Field* const> from, std::span<core::Field* const> to,
            std::span<const int> components, int tag, const std::string& what) override;
  std::vector<double> trade(const std::vector<double>& mine, const std::string& what) override;
  [[nodiscard]] bool inMemory() const override { return true; }
};

}  // namespace mpmice::coupler
