#include "core/time/time_loop.h"

#include <cmath>

namespace mpmice::core {

OutputSchedule::OutputSchedule(double interval, double end) : every_(interval > 0 ? interval : end), end_(end) {}

bool OutputSchedule::due(double t, bool last) {
  if (!reached(t, next_) && !reached(t, end_) && !last) return false;
  // The next multiple of the interval after t, computed (not counted up to: an interval far
  // below the step would take ~t / interval additions).
  if (every_ > 0) {
    next_ = every_ * (std::floor(t / every_ * (1 + kTimeTolerance)) + 1);
    if (next_ <= t * (1 + kTimeTolerance)) next_ = t + every_;
  }
  written_ = t;
  return true;
}

}  // namespace mpmice::core
