#include "study/reference/probe_curve.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace mpmice::study {

CurveDifference curveDifference(const core::TimeSeries& reference, const core::TimeSeries& run) {
  CurveDifference d;
  if (run.t.empty()) throw std::invalid_argument("the run's record is empty");
  double s2 = 0, r2 = 0, sum = 0;
  std::size_t k = 0;  // the run's interval [t_k, t_k+1] holding the sample
  for (std::size_t i = 0; i < reference.t.size(); ++i) {
    const double t = reference.t[i];
    if (t < run.t.front() || t > run.t.back()) continue;
    while (k + 1 < run.t.size() && run.t[k + 1] < t) ++k;
    double u = run.u[k];
    if (k + 1 < run.t.size() && run.t[k + 1] > run.t[k]) {
      const double w = (t - run.t[k]) / (run.t[k + 1] - run.t[k]);
      u = run.u[k] + std::min(1.0, std::max(0.0, w)) * (run.u[k + 1] - run.u[k]);
    }
    const double diff = u - reference.u[i];
    if (d.samples == 0) d.tFirst = t;
    d.tLast = t;
    ++d.samples;
    s2 += diff * diff;
    r2 += reference.u[i] * reference.u[i];
    sum += diff;
    if (std::abs(diff) > std::abs(d.largest)) {
      d.largest = diff;
      d.largestTime = t;
    }
  }
  auto span = [](const core::TimeSeries& s) {
    return s.t.empty() ? std::string("none") : std::to_string(s.t.front()) + " .. " + std::to_string(s.t.back()) + " s";
  };
  if (d.samples < 2)
    throw std::invalid_argument("the run's record (t " + span(run) + ") holds " + std::to_string(d.samples) +
                                " of the reference curve's samples (t " + span(reference) + "); at least 2 are needed");
  const double n = static_cast<double>(d.samples);
  d.rms = std::sqrt(s2 / n);
  d.rmsReference = std::sqrt(r2 / n);
  d.mean = sum / n;
  if (!(d.rmsReference > 0))
    throw std::invalid_argument("the reference curve is 0 over the run's span (t " + span(run) + "): no relative error");
  return d;
}

double probeCurveError(const RunFiles& files) {
  const core::TimeSeries reference = core::readTimeSeriesFile(files.curve, files.column);
  const std::string probes = (std::filesystem::path(files.dir) / (files.name + "_probes.csv")).string();
  if (!std::filesystem::is_regular_file(probes))
    throw std::runtime_error(probes + ": no probes file (the scene's output.probes write it)");
  const core::TimeSeries run = core::readTimeSeriesFile(probes, files.column);
  try {
    return curveDifference(reference, run).relative();
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(probes + " against " + files.curve + ": " + e.what());
  }
}

}  // namespace mpmice::study
