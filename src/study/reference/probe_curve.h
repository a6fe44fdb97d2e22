#pragma once
/// @brief A probe's record against a reference curve (the study's `probe_curve` reference): the
/// run's probes file `<output.directory>/<scene>_probes.csv` and a reference CSV (the same form:
/// comment lines, a header naming `time` and the column) are compared on the reference's samples
/// inside the run's time span, the run's record interpolated linearly there. The error is the
/// root mean square of the difference relative to the reference's own root mean square over the
/// same samples. Made for the flap's tip curve against the MPM + OpenFOAM one
/// (configs/studies/flap_trade.yaml, docs/tradeoffs.md).
#include <cstddef>
#include <string>

#include "core/io/time_series.h"
#include "study/reference/references.h"

namespace mpmice::study {

struct CurveDifference {
  std::size_t samples = 0;      // the reference's samples inside the run's span
  double tFirst = 0, tLast = 0; // their first and last time
  double rms = 0;               // rms(u_run - u_ref)
  double rmsReference = 0;      // rms(u_ref)
  double mean = 0;              // mean(u_run - u_ref)
  double largest = 0, largestTime = 0;  // the largest |u_run - u_ref| (signed) and its time
  [[nodiscard]] double relative() const { return rms / rmsReference; }
};

/// The difference of `run` against `reference` on the reference's samples within the run's span.
/// std::invalid_argument when fewer than 2 samples are shared or the reference is 0 there.
CurveDifference curveDifference(const core::TimeSeries& reference, const core::TimeSeries& run);

/// The study's error of a finished run: curveDifference(the curve of `files.curve`, the run's
/// probes file's `files.column`).relative(). Throws naming the file that cannot be measured.
double probeCurveError(const RunFiles& files);

}  // namespace mpmice::study
