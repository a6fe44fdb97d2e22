// flap_tip: the perpendicular flap's tip figures (first peak, period) from probes CSV files.
//
// Sample runs:  flap_tip output/flap_mpmice/flap_mpmice_probes.csv
//               flap_tip -o tip.csv --smooth 0.02 dx0.05/flap_mpmice_probes.csv dx0.025/flap_mpmice_probes.csv
// 1. Read column `time` and the displacement column (--column, default tip_ux) of each file.
// 2. Measure (tip_metrics.h): first peak and its time, period from up-crossings of u - mean and
//    from successive maxima, the mean; --band sets the hysteresis (fraction of the range, 0.1).
// 3. Write one CSV row per file to stdout or to -o <file>:
//      file,first_peak,first_peak_time,period,period_maxima,crossings,maxima,mean
//    (lengths in m, times in s; nan where the record is too short to tell).
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "tip_metrics.h"

int main(int argc, char** argv) {
  std::string column = "tip_ux", outPath;
  double band = 0.1, smooth = 0.0;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "flap_tip: %s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--column") column = value();
    else if (a == "--band") band = std::stod(value());
    else if (a == "--smooth") smooth = std::stod(value());
    else if (a == "-o") outPath = value();
    else if (a.rfind("-", 0) == 0) {
      std::fprintf(stderr, "flap_tip: unknown option '%s'\n", a.c_str());
      return 2;
    } else {
      files.push_back(a);
    }
  }
  if (files.empty()) {
    std::fprintf(stderr,
                 "usage: flap_tip [--column tip_ux] [--band 0.1] [--smooth seconds] [-o out.csv] probes.csv ...\n");
    return 2;
  }
  std::ofstream file;
  if (!outPath.empty()) file.open(outPath);
  std::ostream& out = outPath.empty() ? std::cout : file;
  out << "file,first_peak,first_peak_time,period,period_maxima,crossings,maxima,mean\n";
  try {
    for (const std::string& f : files) {
      const auto m = mpmice::flap::measureTip(mpmice::core::readTimeSeriesFile(f, column), band, smooth);
      char row[512];
      std::snprintf(row, sizeof row, "%s,%.6g,%.6g,%.6g,%.6g,%d,%d,%.6g\n", f.c_str(), m.firstPeak, m.firstPeakTime,
                    m.period, m.periodMaxima, m.crossings, m.maxima, m.mean);
      out << row;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "flap_tip: %s\n", e.what());
    return 1;
  }
  return 0;
}
