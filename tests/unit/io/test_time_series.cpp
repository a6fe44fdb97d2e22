// core::readTimeSeries: a probe column against time from a probes CSV (columns by name, comment
// and blank lines skipped), and each malformed input an error naming the source, the line and
// the column.
#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <string>

#include "core/io/time_series.h"

using mpmice::core::readTimeSeries;
using mpmice::core::readTimeSeriesFile;
using mpmice::core::TimeSeries;

namespace {

std::string errorOf(const std::string& text, const std::string& column) {
  std::istringstream in(text);
  try {
    readTimeSeries(in, column, "p.csv");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(TimeSeries, ReadsTheColumnsByNameSkippingCommentsAndBlankLines) {
  std::istringstream in(
      "# the flap's tip, MPM + OpenFOAM\n#\nstep,time,tip_x,tip_y,tip_ux,tip_uy\n0,0,0.0125,0.9875,0,0\n\n"
      "  # a comment between rows\n1, 0.5 ,0.1,0.98,0.0875,-0.0075\n2,0.5,0.1,0.98,0.0876,-0.0075\n");
  const TimeSeries s = readTimeSeries(in, "tip_ux");
  ASSERT_EQ(s.t.size(), 3u);
  EXPECT_EQ(s.t[1], 0.5);
  EXPECT_EQ(s.u[1], 0.0875);
  EXPECT_EQ(s.u[2], 0.0876);  // an equal time is kept (a restart writes its step again)
}

TEST(TimeSeries, EachMalformedInputNamesTheSourceTheLineAndTheColumn) {
  EXPECT_NE(errorOf("step,time,tip_x\n", "tip_ux").find("p.csv:1: no column 'tip_ux' in the header 'step,time,tip_x'"),
            std::string::npos);
  EXPECT_NE(errorOf("step,tip_ux\n", "tip_ux").find("no column 'time'"), std::string::npos);
  EXPECT_NE(errorOf("# only comments\n\n", "tip_ux").find("p.csv: no header line"), std::string::npos);
  EXPECT_NE(errorOf("time,u\n0,1\n0.1,abc\n", "u").find("p.csv:3: column 2 ('u'): expected a finite number, got 'abc'"),
            std::string::npos);
  EXPECT_NE(errorOf("time,u\n0,1\n0.1,nan\n", "u").find("p.csv:3: column 2 ('u'): expected a finite number"),
            std::string::npos);
  EXPECT_NE(errorOf("time,x,u\n0,1,2\n0.1,1\n", "u").find("p.csv:3: column 3 ('u'): missing (the line has 2 columns)"),
            std::string::npos);
  EXPECT_NE(errorOf("time,u\n0.2,1\n0.1,1\n", "u").find("p.csv:3: time 0.1 is before the line above's"),
            std::string::npos);
  try {
    readTimeSeriesFile("/nonexistent/probes.csv", "u");
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/probes.csv: cannot read the file"), std::string::npos) << e.what();
  }
}
