#include "tip_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mpmice::flap {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<double> movingAverage(const std::vector<double>& t, const std::vector<double>& u, double window) {
  if (!(window > 0)) return u;
  std::vector<double> out(u.size());
  std::size_t lo = 0, hi = 0;
  double sum = 0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    while (hi < u.size() && t[hi] <= t[i] + window / 2) sum += u[hi++];
    while (t[lo] < t[i] - window / 2) sum -= u[lo++];
    out[i] = sum / double(hi - lo);
  }
  return out;
}

double meanTime(const std::vector<double>& t, const std::vector<double>& u) {
  if (u.size() < 2 || !(t.back() > t.front())) return u.empty() ? kNaN : u.front();
  double s = 0;
  for (std::size_t i = 1; i < u.size(); ++i) s += 0.5 * (u[i] + u[i - 1]) * (t[i] - t[i - 1]);
  return s / (t.back() - t.front());
}

double meanSpacing(const std::vector<double>& x) {
  return x.size() < 2 ? kNaN : (x.back() - x.front()) / double(x.size() - 1);
}
}  // namespace

TipMetrics measureTip(const TipSeries& s, double band, double smooth) {
  TipMetrics m;
  m.firstPeak = m.firstPeakTime = m.period = m.periodMaxima = kNaN;
  if (s.u.size() < 3) return m;
  const std::vector<double> u = movingAverage(s.t, s.u, smooth);
  const std::vector<double>& t = s.t;
  m.mean = meanTime(t, u);
  const auto [mn, mx] = std::minmax_element(u.begin(), u.end());
  const double h = band * (*mx - *mn);
  std::vector<double> ups, peaks;
  int state = 0;                    // -1 below the band, +1 above it, 0 not yet known
  double lastUp = kNaN;             // time u - mean last rose through zero
  double peak = -1e300, peakT = 0;  // maximum of the current upward excursion
  bool first = true;
  for (std::size_t i = 0; i < u.size(); ++i) {
    const double v = u[i] - m.mean;
    if (i > 0) {
      const double w = u[i - 1] - m.mean;
      if (w <= 0 && v > 0) lastUp = t[i - 1] + (t[i] - t[i - 1]) * (-w) / (v - w);
    }
    if (state != 1 && v > h) {  // an upward excursion starts
      if (state == -1 && std::isfinite(lastUp)) ups.push_back(lastUp);
      state = 1;
      peak = -1e300;
    } else if (state != -1 && v < -h) {  // a downward one: the upward one (if any) is complete
      if (state == 1) {
        peaks.push_back(peakT);
        if (first) {
          m.firstPeak = peak;
          m.firstPeakTime = peakT;
          first = false;
        }
      }
      state = -1;
    }
    if (state == 1 && u[i] > peak) {
      peak = u[i];
      peakT = t[i];
    }
  }
  m.crossings = static_cast<int>(ups.size());
  m.maxima = static_cast<int>(peaks.size());
  m.period = meanSpacing(ups);
  m.periodMaxima = meanSpacing(peaks);
  return m;
}

}  // namespace mpmice::flap
