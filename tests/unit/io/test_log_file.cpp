// A program's log file (core/io/log_file.h): appended, never truncated; what std::cout, std::cerr
// and the error lines carry while the tee lives; nothing after it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>

#include "core/io/log_file.h"
#include "core/io/text_file.h"
#include "core/util/error_line.h"
#include "serial_mpi.h"

namespace mpmice::core {
namespace {

Scene logScene(const std::string& dir, bool enabled = true) {
  Scene s = parseScene("scene: logged\nmesh: {dim: 1, lower: [0], upper: [1], cells: [4]}\ntime: {end: 1}\n"
                       "materials:\n  - {name: air, kind: fluid, eos: {type: ideal_gas, gamma: 1.4}}\n"
                       "geometry:\n  - {shape: {type: box, lo: [0], hi: [1]}, material: air, pressure: 1}\n",
                       "logged.yaml");
  s.output.directory = dir;
  s.output.enabled = enabled;
  return s;
}

TEST(LogFile, HoldsWhatTheProgramPrintsAndKeepsWhatWasThere) {
  const std::string dir = MPMICE_IO_TEST_DIR;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const Scene s = logScene(dir);
  const std::string path = logFilePath(s, "ice_solver");
  EXPECT_EQ(path, dir + "/log.ice_solver");
  std::ofstream(path) << "an earlier run's last line\n";  // not this run's: it stays
  const Comm self(MPI_COMM_SELF);
  {
    const auto log = LogFile::teeProgramOutput(self, s, "ice_solver");
    ASSERT_NE(log, nullptr);
    std::cout << "step 1  t = 1.0e-03\n";
    std::cerr << "warning: something\n";
    writeErrorLine("ice_solver", "it failed");
  }
  std::cout << "after the tee\n";
  writeErrorLine("ice_solver", "not logged");
  {
    const auto again = LogFile::teeProgramOutput(self, s, "ice_solver");
    std::cout << "second run\n";
  }
  const std::string text = readTextFile(path);
  EXPECT_EQ(text.rfind("an earlier run's last line\n==== ice_solver ", 0), 0u) << text;
  EXPECT_NE(text.find("scene 'logged' (logged.yaml), started "), std::string::npos) << text;
  EXPECT_NE(text.find("====\nstep 1  t = 1.0e-03\nwarning: something\nice_solver: error: it failed\n==== ice_solver "),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("====\nsecond run\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("after the tee"), std::string::npos) << text;
  EXPECT_EQ(text.find("not logged"), std::string::npos) << text;
  std::filesystem::remove_all(dir);
}

TEST(LogFile, NoneWithoutOutput) {
  const std::string dir = std::string(MPMICE_IO_TEST_DIR) + "_disabled";
  std::filesystem::remove_all(dir);
  EXPECT_EQ(LogFile::teeProgramOutput(Comm(MPI_COMM_SELF), logScene(dir, false), "mpmice"), nullptr);
  EXPECT_FALSE(std::filesystem::exists(dir));
}

TEST(LogFile, AnUnwritableLogNamesTheFile) {
  const std::string dir = std::string(MPMICE_IO_TEST_DIR) + "_blocked";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir + "/log.mpmice");  // a folder where the file would go
  try {
    (void)LogFile::teeProgramOutput(Comm(MPI_COMM_SELF), logScene(dir), "mpmice");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot append to the log file " + dir + "/log.mpmice"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mpmice::core
