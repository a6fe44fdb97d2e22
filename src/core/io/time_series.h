#pragma once
/// @brief One column of a CSV record against time: the probes files the programs write
/// (`<scene>_probes.csv`: step, time, then each probe's columns) and curves kept for comparison.
///
///     # comment lines (a '#' in the first non-blank column) and blank lines anywhere
///     step,time,tip_x,tip_y,tip_ux,tip_uy      <- the header: the columns by name
///     0,0,-0.00625,0.99375,0,0
///
/// The columns `time` and the one asked for are read by name; every other column is ignored.
#include <istream>
#include <string>
#include <vector>

namespace mpmice::core {

struct TimeSeries {
  std::vector<double> t, u;
};

/// Reads columns `time` and `column` from `in`. std::invalid_argument naming `what` (and the line)
/// for no header, a missing column, a cell that is not a finite number, or a time that goes back.
TimeSeries readTimeSeries(std::istream& in, const std::string& column, const std::string& what = "input");

/// The same from the file `path` (an unreadable file is an error naming it).
TimeSeries readTimeSeriesFile(const std::string& path, const std::string& column);

}  // namespace mpmice::core
