// CsvWriter: header and row text, column-count checks, only the chosen rank writes, append mode.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/io/csv_writer.h"

using namespace mpmice::core;
namespace fs = std::filesystem;

namespace {
std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
}  // namespace

TEST(CsvWriter, WritesHeaderAndRowsOfNumbers) {
  std::ostringstream os;
  CsvWriter w(os, {"step", "time", "mass total", "a,b"});
  EXPECT_EQ(os.str(), "step,time,mass total,\"a,b\"\n");
  w.row({1, 1.5e-3, 0.1 + 0.2, -4});
  w.row(std::vector<double>{2, 3e-3, 1.0 / 3.0, 1e20});
  EXPECT_EQ(os.str(), "step,time,mass total,\"a,b\"\n"
                      "1,0.0015,0.3,-4\n"
                      "2,0.003,0.333333333333,1e+20\n");
}

TEST(CsvWriter, PrecisionIsConfigurable) {
  std::ostringstream os;
  CsvWriter w(os, {"x"}, true, 17);
  w.row({0.1 + 0.2});
  EXPECT_EQ(os.str(), "x\n0.30000000000000004\n");
}

TEST(CsvWriter, RejectsRowsOfTheWrongLength) {
  std::ostringstream os;
  CsvWriter w(os, {"a", "b"});
  EXPECT_THROW(w.row({1.0}), std::invalid_argument);
  EXPECT_THROW(w.row({1.0, 2.0, 3.0}), std::invalid_argument);
  // An inactive writer (another rank) checks too, but writes nothing.
  std::ostringstream quiet;
  CsvWriter q(quiet, {"a", "b"}, false);
  q.row({1, 2});
  EXPECT_THROW(q.row({1}), std::invalid_argument);
  EXPECT_EQ(quiet.str(), "");
}

TEST(CsvWriter, FileOnTheChosenRankFlushedEachRowAndAppendKeepsOneHeader) {
  const fs::path dir = MPMICE_IO_TEST_DIR;
  fs::remove_all(dir);
  fs::create_directories(dir);
  const Comm serial;  // rank 0 of 1, no MPI needed
  const fs::path p = dir / "monitor.csv";
  {
    CsvWriter w(serial, p.string(), {"step", "mass"});
    w.row({0, 1.0});
    EXPECT_EQ(slurp(p), "step,mass\n0,1\n");  // flushed while the writer is open
  }
  {
    CsvWriter w(serial, p.string(), {"step", "mass"}, 0, CsvWriter::Mode::Append);
    w.row({1, 0.5});
  }
  EXPECT_EQ(slurp(p), "step,mass\n0,1\n1,0.5\n");
  // A writer told to write on rank 1 is inactive on rank 0 and creates no file.
  const fs::path other = dir / "other.csv";
  CsvWriter none(serial, other.string(), {"x"}, 1);
  none.row({3});
  EXPECT_FALSE(none.active());
  EXPECT_FALSE(fs::exists(other));
  fs::remove_all(dir);
}
