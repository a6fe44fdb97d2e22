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
#include <map>
#include <span>
#include <string>
#include <vector>

#include "core/field/field.h"

namespace mpmice::coupler {

class Transport {
 public:
  virtual ~Transport() = default;
  /// Moves `from` (the producer's fields, empty when the producer runs elsewhere) into `to` (the
  /// consumer's, same order and components; empty when the consumer runs elsewhere): of field i
  /// its first `components[i]` components (what the consumer reads; the others stay as they
  /// are). `tag` is unique per exchange point and slot; `what` names the data in timeout messages.
  virtual void move(std::span<const core::Field* const> from, std::span<core::Field* const> to,
                    std::span<const int> components, int tag, const std::string& what) = 0;
  /// The peer's values of `mine` (same length on both sides).
  virtual std::vector<double> trade(const std::vector<double>& mine, const std::string& what) = 0;
  /// Wall time spent in move() and trade() so far [s].
  [[nodiscard]] double seconds() const { return seconds_; }
  /// Exchange points moved (move() calls with data on this side) and scalar trades so far.
  [[nodiscard]] long moves() const { return moves_; }
  [[nodiscard]] long trades() const { return trades_; }
  /// Both sides call it at the same point of the run: the median wall time of `rounds` swaps of
  /// one double between the leaders [s] (0 in one process, where nothing crosses).
  virtual double measureLatency(int /*rounds*/) { return 0.0; }
  /// True when both sides run in this process.
  [[nodiscard]] virtual bool inMemory() const = 0;

  /// Per exchange point (tag): what it carries, how often it moved, its wall time [s] (waiting
  /// for the peer included) and the bytes it carried (sent or received by this process).
  struct PointStats {
    std::string what;
    long moves = 0;
    double seconds = 0;
    long long bytes = 0;
  };
  [[nodiscard]] const std::map<int, PointStats>& points() const { return points_; }
  /// Bytes this process sent and received in move() so far.
  [[nodiscard]] long long bytes() const {
    long long b = 0;
    for (const auto& [tag, p] : points_) b += p.bytes;
    return b;
  }

 protected:
  /// Counts one move of point `tag` (`what` up to its " (" qualifier names it).
  void account(int tag, const std::string& what, double seconds, long long bytes) {
    PointStats& p = points_[tag];
    if (p.what.empty()) p.what = what.substr(0, what.find(" ("));
    ++p.moves;
    p.seconds += seconds;
    p.bytes += bytes;
  }
  double seconds_ = 0;
  long moves_ = 0, trades_ = 0;

 private:
  std::map<int, PointStats> points_;
};


}  // namespace mpmice::coupler
