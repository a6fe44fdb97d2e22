// The run record (src/core/io/run_record.h): what a run was, written at the start ("running")
// and rewritten at the end ("completed"), with the scene as understood and its hash.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/io/run_record.h"
#include "serial_mpi.h"

namespace mpmice::core {
namespace {

std::string slurp(const std::string& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

TEST(RunRecord, NamesProgramVersionSceneAndStatus) {
  Scene s = parseScene("mesh: {dim: 1, lower: [0], upper: [1], cells: [4]}\ntime: {end: 1}\n"
                       "materials:\n  - {name: air, kind: fluid, eos: {type: ideal_gas, gamma: 1.4}}\n"
                       "geometry:\n  - {shape: {type: box, lo: [0], hi: [1]}, material: air, pressure: 1}\n",
                       "rec.yaml");
  s.output.directory = MPMICE_IO_TEST_DIR;
  std::filesystem::remove_all(s.output.directory);
  const Comm self(MPI_COMM_SELF);
  RunRecord r(s, self, "ice_solver");
  std::string text = slurp(r.path());
  EXPECT_NE(text.find("program: ice_solver"), std::string::npos) << text;
  EXPECT_NE(text.find("version: \""), std::string::npos) << text;
  EXPECT_NE(text.find("status: running"), std::string::npos) << text;
  EXPECT_NE(text.find("scene_hash: " + sceneHash(s)), std::string::npos) << text;
  EXPECT_NE(text.find("scene_as_understood: |\n  "), std::string::npos) << text;
  EXPECT_NE(text.find("ended: null"), std::string::npos) << text;
  r.completed();
  text = slurp(r.path());
  EXPECT_NE(text.find("status: completed"), std::string::npos) << text;
  EXPECT_EQ(text.find("ended: null"), std::string::npos) << text;
  EXPECT_FALSE(std::filesystem::exists(r.path() + ".part"));
}

}  // namespace
}  // namespace mpmice::core
