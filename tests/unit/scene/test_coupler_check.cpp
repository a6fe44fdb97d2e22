// Runs the real `coupler check` program: a good scene exits 0 and prints the scene as
// understood; a bad one exits non-zero with the scene error on stderr; usage on --help.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

struct Result {
  int status = -1;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class CouplerCheck : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("coupler_check_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p;
  }

  Result run(const std::string& args) {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string cmd = std::string("'") + COUPLER_EXE + "' " + args + " > '" + out.string() + "' 2> '" +
                            err.string() + "'";
    const int raw = std::system(cmd.c_str());
    Result r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }

  fs::path dir_;
};

TEST_F(CouplerCheck, GoodSceneExitsZeroAndPrintsTheScene) {
  const Result r = run(std::string("check '") + MPMICE_SOURCE_DIR + "/configs/sod.yaml'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("scene: sod"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("cfl: 0.4"), std::string::npos) << r.out;  // defaults filled in
  EXPECT_NE(r.out.find("# ok: scene 'sod': 1D, 100 cells"), std::string::npos) << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST_F(CouplerCheck, ItsOutputIsAValidSceneAgain) {
  const Result first = run(std::string("check '") + MPMICE_SOURCE_DIR + "/configs/pressurized_cylinder.yaml'");
  ASSERT_EQ(first.status, 0) << first.err;
  const fs::path again = write("again.yaml", first.out);
  const Result second = run("check '" + again.string() + "'");
  EXPECT_EQ(second.status, 0) << second.err;
  // Same scene, same hash (the last line carries it).
  EXPECT_EQ(first.out.substr(first.out.find("hash ")), second.out.substr(second.out.find("hash ")));
}

TEST_F(CouplerCheck, BadSceneExitsNonZeroWithTheMessageOnStderr) {
  const fs::path bad = write("bad.yaml",
                             "mesh: {dim: 1, lower: [0], upper: [1], cells: [10]}\n"
                             "time: {end: 1, cfl: 1.5}\n"
                             "materials: [{name: air, kind: fluid, eos: {type: ideal_gas, gamma: 1.4}}]\n"
                             "geometry: [{shape: {type: box, lo: [0], hi: [1]}, material: air, pressure: 1}]\n");
  const Result r = run("check '" + bad.string() + "'");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find(bad.string() + ":2:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("time.cfl: 1.5 is out of range; expected a number in (0, 1]"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST_F(CouplerCheck, MissingFileIsAnError) {
  const Result r = run("check '" + (dir_ / "nope.yaml").string() + "'");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("nope.yaml"), std::string::npos) << r.err;
}

TEST_F(CouplerCheck, UsageOnHelpAndUnknownCommand) {
  const Result help = run("--help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("usage: coupler"), std::string::npos) << help.out;
  const Result unknown = run("chek x.yaml");
  EXPECT_NE(unknown.status, 0);
  EXPECT_NE(unknown.err.find("unknown command 'chek'"), std::string::npos) << unknown.err;
  EXPECT_NE(unknown.err.find("did you mean 'check'?"), std::string::npos) << unknown.err;
  EXPECT_NE(unknown.err.find("usage: coupler"), std::string::npos) << unknown.err;
  const Result none = run("");
  EXPECT_NE(none.status, 0);
}

}  // namespace
