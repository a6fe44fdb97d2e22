// The run's description in the root attributes of every HDF5 file it writes
// (core/io/run_metadata.h): what the run record (<scene>_run.yaml) holds, the same bytes on every
// rank, read back from the file. Run with 1 and 2 ranks.
#include <gtest/gtest.h>

#include <filesystem>
#include <yaml-cpp/yaml.h>

#include "core/io/h5_file.h"
#include "core/io/output_writer.h"
#include "core/io/run_record.h"
#include "core/parallel/mpi_session.h"
#include "core/version.h"
#include "test_comm.h"

using namespace mpmice::core;
namespace fs = std::filesystem;

namespace {

Scene tinyScene(const std::string& dir) {
  Scene s = parseScene("scene: described\nmesh: {dim: 2, lower: [0, 0], upper: [1, 1], cells: [4, 3]}\ntime: {end: 1}\n"
                       "materials:\n  - {name: air, kind: fluid, eos: {type: ideal_gas, gamma: 1.4}}\n"
                       "geometry:\n  - {shape: {type: box, lo: [0, 0], hi: [1, 1]}, material: air, pressure: 1}\n",
                       "described.yaml");
  s.output.directory = dir;
  return s;
}

std::string trimmed(std::string s) {
  while (!s.empty() && s.back() == '\n') s.pop_back();
  return s;
}

TEST(RunMetadata, EveryOutputFileCarriesTheRunRecordAsRootAttributes) {
  const Comm& comm = mpmice::test::comm();
  const std::string dir = std::string(MPMICE_IO_TEST_DIR) + "_np" + std::to_string(comm.size());
  if (comm.root()) fs::remove_all(dir);
  comm.barrier();
  const Scene scene = tinyScene(dir);
  std::string h5;
  {
    RunRecord record(scene, comm, "ice_solver");
    ASSERT_EQ(RunMetadata::current(), &record.metadata());
    const Decomposition decomp(scene.mesh, comm.size());
    OutputWriter writer(comm, decomp, dir, scene.name);
    Field p("pressure", Centering::Cell, decomp.storedBox(comm.rank(), Centering::Cell, 1), 1, 1, 1.0);
    h5 = writer.writeStep(0, 0.0, {&p});
    record.completed();
  }
  EXPECT_EQ(RunMetadata::current(), nullptr);  // the record's end ends its publication
  comm.barrier();
  const H5File file = H5File::open(h5);
  const RunMetadata m = RunMetadata::readFrom(file.root());
  EXPECT_EQ(m.program, "ice_solver");
  EXPECT_EQ(m.version, std::string(kProjectVersion) + " (" + kGitDescribe + ")");
  EXPECT_EQ(m.command_line, MpiSession::commandLine());
  EXPECT_FALSE(m.command_line.empty());
  EXPECT_EQ(m.ranks, comm.size());
  EXPECT_EQ(m.launch_ranks, MpiSession::worldSize());
  EXPECT_EQ(m.rank_layout, comm.size() == 1 ? "ice_solver: 1 rank" : "ice_solver: " + std::to_string(comm.size()) + " ranks");
  EXPECT_EQ(m.scene_file, "described.yaml");
  EXPECT_EQ(m.scene_hash, sceneHash(scene));
  EXPECT_EQ(m.scene_as_understood, dumpScene(scene));
  EXPECT_NE(m.scene_as_understood.find("scene: described"), std::string::npos) << m.scene_as_understood;
  EXPECT_EQ(m.started.size(), std::string("2026-12-01T23:10:00Z").size()) << m.started;
  // The same facts as the run record, value for value.
  const YAML::Node rec = YAML::LoadFile(dir + "/described_run.yaml");
  EXPECT_EQ(rec["program"].as<std::string>(), m.program);
  EXPECT_EQ(rec["version"].as<std::string>(), m.version);
  EXPECT_EQ(rec["command_line"].as<std::string>(), m.command_line);
  EXPECT_EQ(rec["ranks"].as<long>(), m.ranks);
  EXPECT_EQ(rec["launch_ranks"].as<long>(), m.launch_ranks);
  EXPECT_EQ(rec["rank_layout"].as<std::string>(), m.rank_layout);
  EXPECT_EQ(rec["host"].as<std::string>(), m.host);
  EXPECT_EQ(rec["started"].as<std::string>(), m.started);
  EXPECT_EQ(rec["scene_hash"].as<std::string>(), m.scene_hash);
  EXPECT_EQ(trimmed(rec["scene_as_understood"].as<std::string>()), trimmed(m.scene_as_understood));
  // Every rank wrote the same bytes: what rank 0 read, every rank read.
  EXPECT_EQ(comm.firstMessage(comm.root() ? m.started + m.host + m.command_line : ""), m.started + m.host + m.command_line);
  comm.barrier();
  if (comm.root()) fs::remove_all(dir);
}

TEST(RunMetadata, AMissingAttributeNamesItAndTheFile) {
  const Comm& comm = mpmice::test::comm();
  const std::string path = std::string(MPMICE_IO_TEST_DIR) + "_bare_np" + std::to_string(comm.size()) + ".h5";
  if (comm.root()) {
    const H5File f = H5File::create(path);
    f.root().writeAttribute("program", std::string("mpm_solver"));
  }
  comm.barrier();
  const H5File f = H5File::open(path);
  EXPECT_EQ(f.root().readAttributeString("program"), "mpm_solver");
  try {
    (void)RunMetadata::readFrom(f.root());
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("no attribute 'version'"), std::string::npos) << msg;
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
  }
  comm.barrier();
  if (comm.root()) fs::remove(path);
}

}  // namespace
