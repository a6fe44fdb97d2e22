#include "coupler/transport/in_memory_transport.h"

#include <stdexcept>
#include <utility>

#include "coupler/transport/stopwatch.h"

namespace mpmice::coupler {

void InMemoryTransport::move(std::span<const core::Field* const> from, std::span<core::Field* const> to,
                             std::span<const int> components, int tag, const std::string& what) {
  double seconds = 0;
  long long bytes = 0;
  {
    const Stopwatch total(seconds_), point(seconds);
    ++moves_;
    if (from.size() != to.size() || components.size() != from.size())
      throw std::logic_error("in-memory transport: " + what + ": " + std::to_string(from.size()) +
                             " fields produced, " + std::to_string(to.size()) + " consumed, " +
                             std::to_string(components.size()) + " declared");
    for (std::size_t i = 0; i < from.size(); ++i) {
      const core::Box& src = from[i]->box();
      const core::Box& dst = to[i]->box();
      if (components[i] == from[i]->ncomp()) {
        to[i]->copyRegion(*from[i], src, dst);
      } else {  // the components the consumer reads; the others stay as they are
        const core::IntVect off{src.lo[0] - dst.lo[0], src.lo[1] - dst.lo[1], src.lo[2] - dst.lo[2]};
        for (int c = 0; c < components[i]; ++c) {
          auto out = to[i]->view(c);
          const auto in = std::as_const(*from[i]).view(c);
          core::forEach(dst, [&](int a, int b, int k) { out(a, b, k) = in(a + off[0], b + off[1], k + off[2]); });
        }
      }
      bytes += static_cast<long long>(sizeof(double)) * dst.numPts() * components[i];
    }
  }
  account(tag, what, seconds, bytes);
}

std::vector<double> InMemoryTransport::trade(const std::vector<double>& mine, const std::string& /*what*/) {
  ++trades_;
  return mine;
}

}  // namespace mpmice::coupler
