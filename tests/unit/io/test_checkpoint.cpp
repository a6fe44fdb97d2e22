// Checkpoint files: every rank's arrays come back exactly (lengths differing between ranks, an
// empty one, NaN and denormal values, text), the file appears only complete (no .part left),
// PATH resolution (a directory's latest, the sibling of another base), and the refusals: another
// rank count, a missing file, a directory without checkpoints, a missing entry. Also the two
// pieces of run state a checkpoint carries: the XDMF index (serialize/restore) and the CSV cut.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/io/checkpoint.h"
#include "core/io/csv_writer.h"
#include "core/io/xdmf_writer.h"
#include "test_comm.h"

using namespace mpmice;
using namespace mpmice::core;
namespace fs = std::filesystem;

namespace {
const std::string kDir = MPMICE_IO_TEST_DIR;

std::string dirFor(const std::string& name) {
  const Comm& comm = test::comm();
  const std::string d = kDir + "/" + name + "_np" + std::to_string(comm.size());
  if (comm.root()) {
    fs::remove_all(d);
    fs::create_directories(d);
  }
  comm.barrier();
  return d;
}

std::vector<double> valuesOf(int rank) {
  std::vector<double> v;
  for (int i = 0; i < 3 * rank + 2; ++i) v.push_back(std::sqrt(2.0) * (i + 1) + rank);
  v.push_back(std::numeric_limits<double>::denorm_min());
  v.push_back(std::numeric_limits<double>::quiet_NaN());
  v.push_back(-0.0);
  return v;
}
}  // namespace

TEST(Checkpoint, EveryRankGetsItsArraysBackExactly) {
  const Comm& comm = test::comm();
  const std::string dir = dirFor("roundtrip");
  CheckpointData d;
  d.put("a.values", valuesOf(comm.rank()));
  d.put("a.empty", std::vector<double>{});
  d.put("b.clock", 0.1 + 0.2);
  d.putText("c.text", "line one\n\tline two " + std::to_string(comm.rank()));
  const std::string path = checkpointPath(dir, "base", 42);
  EXPECT_EQ(path, dir + "/base_checkpoint_000042.h5");
  writeCheckpoint(comm, path, d, 1.5, 42);
  EXPECT_TRUE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".part"));
  const CheckpointData r = readCheckpoint(comm, path);
  const auto want = valuesOf(comm.rank());
  const auto& got = r.get("a.values");
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    std::uint64_t a = 0, b = 0;
    std::memcpy(&a, &want[i], 8);
    std::memcpy(&b, &got[i], 8);
    EXPECT_EQ(a, b) << "value " << i;  // bit for bit (NaN, -0 and denormals included)
  }
  EXPECT_TRUE(r.get("a.empty").empty());
  EXPECT_EQ(r.scalar("b.clock"), 0.1 + 0.2);
  EXPECT_EQ(r.text("c.text"), "line one\n\tline two " + std::to_string(comm.rank()));
  EXPECT_EQ(r.source(), path);
  try {
    (void)r.get("no.such");
    ADD_FAILURE() << "a missing entry must throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no entry 'no.such'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  std::vector<double> wrong(1);
  EXPECT_THROW(r.copyTo("a.values", wrong), std::invalid_argument);
}

TEST(Checkpoint, AnotherRankCountIsRefused) {
  const Comm& comm = test::comm();
  const std::string dir = dirFor("ranks");
  const std::string path = dir + "/one_checkpoint_000001.h5";
  // Written by rank 0 alone (a 1-rank run); read by this run's ranks.
  if (comm.root()) {
    CheckpointData d;
    d.put("x", 1.0);
    writeCheckpoint(Comm(MPI_COMM_SELF), path, d, 0.0, 1);
  }
  comm.barrier();
  if (comm.size() == 1) {
    EXPECT_EQ(readCheckpoint(comm, path).scalar("x"), 1.0);
    return;
  }
  try {
    (void)readCheckpoint(comm, path);
    ADD_FAILURE() << "another rank count must be refused";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("written by 1 ranks, this run has " + std::to_string(comm.size())),
              std::string::npos)
        << e.what();
  }
}

TEST(Checkpoint, PathMeansTheLatestOrTheSiblingOfTheSameStep) {
  const Comm& comm = test::comm();
  const std::string dir = dirFor("resolve");
  if (comm.root())
    for (const char* f : {"s_solid_checkpoint_000010.h5", "s_solid_checkpoint_000200.h5", "s_fluid_checkpoint_000010.h5",
                          "s_fluid_checkpoint_000200.h5", "s_solid_checkpoint_000300.h5.part", "s_solid_000900.h5"})
      std::ofstream(dir + "/" + f) << "x";
  comm.barrier();
  EXPECT_EQ(resolveCheckpoint(dir, "s_solid"), dir + "/s_solid_checkpoint_000200.h5");
  EXPECT_EQ(resolveCheckpoint(dir + "/s_solid_checkpoint_000010.h5", "s_fluid"), dir + "/s_fluid_checkpoint_000010.h5");
  EXPECT_EQ(resolveCheckpoint(dir + "/s_fluid_checkpoint_000200.h5", "s_fluid"), dir + "/s_fluid_checkpoint_000200.h5");
  auto refused = [](const std::string& path, const std::string& base, const std::string& what) {
    try {
      (void)resolveCheckpoint(path, base);
      ADD_FAILURE() << path << " must be refused";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  refused(dir, "other", "holds no checkpoint other_checkpoint_<step>.h5");
  refused(dir + "/s_solid_checkpoint_000020.h5", "s_solid", "no checkpoint file");
  refused(dir + "/s_solid_000900.h5", "s_solid", "neither an output directory nor a checkpoint file");
  try {
    (void)readCheckpoint(comm, dir + "/missing_checkpoint_000001.h5");
    ADD_FAILURE() << "a missing file must be refused";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no checkpoint file"), std::string::npos) << e.what();
  }
}

TEST(Checkpoint, TheXdmfIndexSurvivesSerialization) {
  Mesh mesh;  // the text does not depend on the mesh
  XdmfWriter a(mesh);
  XdmfStep s;
  s.step = 0;
  s.time = 0.0;
  s.h5file = "run_000000.h5";
  s.grid = {{"pressure", Centering::Cell, 1}, {"velocity", Centering::Node, 3}};
  s.numParticles = 7;
  s.particles = {{"mass", 1}, {"stress", 6}};
  a.add(s);
  s.step = 12;
  s.time = 0.1 + 0.2;
  s.h5file = "run_000012.h5";
  s.numParticles = -1;
  s.particles.clear();
  a.add(s);
  XdmfWriter b(mesh);
  b.restore(a.serialize());
  ASSERT_EQ(b.steps().size(), 2u);
  EXPECT_EQ(b.steps()[1].time, 0.1 + 0.2);  // exact
  EXPECT_EQ(b.steps()[1].numParticles, -1);
  EXPECT_EQ(b.steps()[0].grid[1].centering, Centering::Node);
  EXPECT_EQ(b.steps()[0].particles[1].ncomp, 6);
  EXPECT_EQ(b.serialize(), a.serialize());
  EXPECT_EQ(b.text(), a.text());
}

TEST(Checkpoint, ACsvResumesAfterTheRowsItHadAtTheCheckpoint) {
  const Comm& comm = test::comm();
  const std::string dir = dirFor("csv");
  const std::string path = dir + "/t.csv";
  std::int64_t length = 0;
  {
    CsvWriter w(comm, path, {"step", "x"});
    w.row({1, 0.5});
    length = w.length();  // the checkpoint
    w.row({2, 0.25});     // written after it by the run that was killed
  }
  CsvWriter::cutForResume(comm, path, comm.root() ? length : 0);
  {
    CsvWriter w(comm, path, {"step", "x"}, 0, CsvWriter::Mode::Append);
    w.row({2, 0.125});
  }
  if (comm.root()) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    EXPECT_EQ(ss.str(), "step,x\n1,0.5\n2,0.125\n");
  }
  comm.barrier();
  EXPECT_THROW(CsvWriter::cutForResume(comm, dir + "/missing.csv", 10), std::invalid_argument);
  EXPECT_THROW(CsvWriter::cutForResume(comm, path, 1000000), std::invalid_argument);
}
