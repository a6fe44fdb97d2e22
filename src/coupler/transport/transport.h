#pragma once
/// @brief How coupled data cross between the two sides of a coupling, whatever carries them.
///
/// A coupling names its exchange points and calls move() for each: the producing side's fields
/// go into the consuming side's. A side that runs in another process is absent here: its field
/// list is empty, and the transport sends (this process produces) or receives (it consumes)
/// instead of copying. trade() gives each side the other's values of a few scalars (the time
/// step, the verdict of an iteration, totals); in one process the peer is this process itself,
/// so trade() returns its argument. Two implementations: InMemoryTransport (both sides in one
/// process, the in-process driver) and MpiTransport (rank to rank over an MPMD launch's
/// inter-communicator). Every transport counts the wall time it spends.
#include <span>
#include <string>
#include <vector>

#include "core/field/field.h"

namespace mpmice::coupler {

class Transport {
 public:
  virtual ~Transport() = default;
  /// Moves `from` (the producer's fields, empty when the producer runs elsewhere) into `to` (the
  /// consumer's, same order and components; empty when the consumer runs elsewhere). `tag` is
  /// unique per exchange point and slot; `what` names the data in timeout messages.
  virtual void move(std::span<const core::Field* const> from, std::span<core::Field* const> to, int tag,
                    const std::string& what) = 0;
  /// The peer's values of `mine` (same length on both sides).
  virtual std::vector<double> trade(const std::vector<double>& mine, const std::string& what) = 0;
  /// Wall time spent in move() and trade() so far [s].
  [[nodiscard]] double seconds() const { return seconds_; }
  /// Exchange points moved (move() calls with data on this side) and scalar trades so far.
  [[nodiscard]] long moves() const { return moves_; }
  [[nodiscard]] long trades() const { return trades_; }
  /// True when both sides run in this process.
  [[nodiscard]] virtual bool inMemory() const = 0;

 protected:
  double seconds_ = 0;
  long moves_ = 0, trades_ = 0;
};

}  // namespace mpmice::coupler
