#pragma once
/// @brief The acceptance verdict of an implicit coupling iteration (preCICE's rule).
///
/// Each convergence measure of a step either holds or not, and is "strict" or "suffices".
/// Iteration k of a step is accepted when k >= min_iterations and
///   - every measure holds, or
///   - a suffices measure holds and no strict measure fails.
/// A failing strict measure always overrules a holding suffices one. Without any measure
/// nothing is ever accepted (the caller supplies defaults).
#include <span>

namespace mpmice::coupler {

struct MeasureOutcome {
  bool holds = false;
  bool strict = false;
};

[[nodiscard]] bool stepAccepted(int iteration, int minIterations, std::span<const MeasureOutcome> outcomes);

}  // namespace mpmice::coupler
