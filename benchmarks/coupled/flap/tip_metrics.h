#pragma once
/// @brief Figures of the perpendicular flap's tip displacement: first peak, period, mean.
///
/// The signal is a probe column (tip_ux) against time, a damped oscillation about a static
/// deflection with small numerical noise on top. Excursions of u - mean beyond a hysteresis band
/// (a fraction of the signal's range) are counted, so noise near the mean makes no crossings:
///  - first peak: the largest u of the first excursion above the band, and its time;
///  - period: mean time between successive zero-up-crossings of u - mean (crossing times
///    interpolated linearly, the last one inside the band before each upward excursion), and
///    for comparison the mean time between the maxima of successive upward excursions;
///  - mean: the time average of u over the whole record (trapezoidal).
/// An optional centred moving average (window in seconds) smooths the signal first.
#include "core/io/time_series.h"

namespace mpmice::flap {

/// The tip's record: a probe column against time (core::readTimeSeries reads it from a probes CSV).
using TipSeries = core::TimeSeries;

struct TipMetrics {
  double firstPeak = 0, firstPeakTime = 0;  // NaN when no upward excursion was found
  double period = 0;                        // from up-crossings; NaN with fewer than two
  double periodMaxima = 0;                  // from successive maxima; NaN with fewer than two
  int crossings = 0, maxima = 0;
  double mean = 0;
};

/// The figures of u(t). `band` is the hysteresis half-width as a fraction of max(u) - min(u);
/// `smooth` the moving-average window [s] (0: none).
TipMetrics measureTip(const TipSeries& s, double band = 0.1, double smooth = 0.0);

}  // namespace mpmice::flap
