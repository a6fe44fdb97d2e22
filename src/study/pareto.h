#pragma once
/// @brief The speed-accuracy trade of a study: the Pareto front (no other point is both cheaper
/// and more accurate) and its plot, error against cost (wall or CPU time), log-log, every point
/// labelled.
#include <string>
#include <vector>

namespace mpmice::study {

struct TradePoint {
  std::string label;
  double cost = 0, error = 0;  // cost: the run's wall or CPU time [s]
};

/// The indices of the front, cheapest first: a point is on it when no point with a cost at most
/// its own has a smaller error (ties in cost: the smaller error). Points whose cost or error is
/// not finite and > 0 are left out.
std::vector<std::size_t> paretoFront(const std::vector<TradePoint>& pts);

/// Writes `<prefix>_pareto.dat` and `<prefix>_pareto.gp` and runs gnuplot (no shell) to draw
/// `<prefix>_pareto.png`, the cost axis labelled `costLabel`. Returns "" when drawn, otherwise
/// why not (gnuplot missing or failed; no point to draw).
std::string plotPareto(const std::vector<TradePoint>& pts, const std::string& prefix, const std::string& title,
                       const std::string& costLabel = "wall time per run [s]");

}  // namespace mpmice::study
