#include "study/pareto.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <numeric>

#include "coupler/cli/process.h"

namespace mpmice::study {

namespace {
bool usable(const TradePoint& p) { return std::isfinite(p.cost) && std::isfinite(p.error) && p.cost > 0 && p.error > 0; }

std::string quoted(const std::string& s) {  // a gnuplot string in double quotes
  std::string q = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') q.push_back('\\');
    q.push_back(c);
  }
  return q + "\"";
}
}  // namespace

std::vector<std::size_t> paretoFront(const std::vector<TradePoint>& pts) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (usable(pts[i])) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return pts[a].cost != pts[b].cost ? pts[a].cost < pts[b].cost : pts[a].error < pts[b].error;
  });
  std::vector<std::size_t> front;
  double best = INFINITY;
  for (std::size_t i : order)
    if (pts[i].error < best) {
      front.push_back(i);
      best = pts[i].error;
    }
  return front;
}

std::string plotPareto(const std::vector<TradePoint>& pts, const std::string& prefix, const std::string& title,
                       const std::string& costLabel) {
  const auto front = paretoFront(pts);
  if (front.empty()) return "no point has a finite error and cost to draw";
  {
    std::ofstream dat(prefix + "_pareto.dat");
    dat << std::setprecision(10) << "# cost_s error label side (every usable point; side: label above or below)\n";
    int side = 0;
    for (const auto& p : pts)
      if (usable(p)) dat << p.cost << ' ' << p.error << ' ' << quoted(p.label) << ' ' << (side++ % 2) << '\n';
    dat << "\n\n# the Pareto front, fastest first\n";
    for (std::size_t i : front) dat << pts[i].cost << ' ' << pts[i].error << ' ' << quoted(pts[i].label) << '\n';
  }
  double w0 = INFINITY, w1 = 0, e0 = INFINITY, e1 = 0;
  for (const auto& p : pts)
    if (usable(p)) {
      w0 = std::min(w0, p.cost);
      w1 = std::max(w1, p.cost);
      e0 = std::min(e0, p.error);
      e1 = std::max(e1, p.error);
    }
  const std::string png = prefix + "_pareto.png";
  {
    std::ofstream gp(prefix + "_pareto.gp");
    gp << "set terminal pngcairo size 1000,700 font ',10'\nset output " << quoted(png) << "\n"
       << "set logscale xy\nset grid xtics ytics mxtics mytics\nset key top right\n"
       << "set xlabel " << quoted(costLabel) << "\nset ylabel 'error against the reference'\n"
       << "set title " << quoted(title) << " noenhanced\n"
       << "set xrange [" << w0 / 1.5 << ":" << w1 * 4 << "]\nset yrange [" << e0 / 1.5 << ":" << e1 * 1.5 << "]\n"
       << "plot " << quoted(prefix + "_pareto.dat") << " index 0 using 1:2 with points pt 7 ps 1.2 title 'runs', \\\n"
       << "  '' index 1 using 1:2 with linespoints lw 2 pt 6 ps 2 title 'Pareto front', \\\n"
       << "  '' index 0 using 1:($4 == 0 ? $2 : 1/0):3 with labels left offset 0.8,0.5 font ',8' noenhanced notitle, \\\n"
       << "  '' index 0 using 1:($4 == 1 ? $2 : 1/0):3 with labels left offset 0.8,-0.5 font ',8' noenhanced notitle\n";
  }
  try {
    const int rc = coupler::runToFile({"gnuplot", prefix + "_pareto.gp"}, prefix + "_pareto.log");
    if (rc != 0) return "gnuplot ended " + std::to_string(rc) + " (see " + prefix + "_pareto.log)";
  } catch (const std::exception&) {
    return "gnuplot is not installed (apt-get install -y gnuplot-nox)";
  }
  return "";
}

}  // namespace mpmice::study
