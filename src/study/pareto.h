#pragma once
/// @brief The speed-accuracy trade of a study: the Pareto front (no other point is both faster
/// and more accurate) and its plot, error against wall time, log-log, every point labelled.
#include <string>
#include <vector>

namespace mpmice::study {

struct TradePoint {
  std::string label;
  double wall = 0, error = 0;
};

/// The indices of the front, fastest first: a point is on it when no point with a wall time at
/// most its own has a smaller error (ties in wall time: the smaller error). Points whose wall
/// time or error is not finite and > 0 are left out.
std::vector<std::size_t> paretoFront(const std::vector<TradePoint>& pts);

/// Writes `<prefix>_pareto.dat` and `<prefix>_pareto.gp` and runs gnuplot (no shell) to draw
/// `<prefix>_pareto.png`. Returns "" when drawn, otherwise why not (gnuplot missing or failed;
/// no point to draw).
std::string plotPareto(const std::vector<TradePoint>& pts, const std::string& prefix, const std::string& title);

}  // namespace mpmice::study
