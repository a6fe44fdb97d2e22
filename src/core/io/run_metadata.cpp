#include "core/io/run_metadata.h"

#include <chrono>
#include <ctime>
#include <unistd.h>

#include "core/io/h5_file.h"
#include "core/parallel/mpi_session.h"
#include "core/version.h"

namespace mpmice::core {

std::string utcNow() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char b[32];
  std::strftime(b, sizeof b, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return b;
}

namespace {

const RunMetadata*& published() {
  static const RunMetadata* m = nullptr;
  return m;
}

/// The string fields by attribute name.
template <class M, class F>
void eachString(M& m, F&& f) {
  f("program", m.program);
  f("version", m.version);
  f("command_line", m.command_line);
  f("rank_layout", m.rank_layout);
  f("host", m.host);
  f("started", m.started);
  f("scene_file", m.scene_file);
  f("scene_hash", m.scene_hash);
  f("scene_as_understood", m.scene_as_understood);
}

/// Rank 0's string on every rank (firstMessage takes the lowest rank with a non-empty one).
std::string fromRoot(const Comm& comm, const std::string& mine) {
  return comm.firstMessage(comm.root() ? (mine.empty() ? std::string(1, '\0') : mine) : std::string());
}

}  // namespace

RunMetadata RunMetadata::describe(const Scene& scene, const Comm& comm, const std::string& program) {
  RunMetadata m;
  m.program = program;
  m.version = std::string(kProjectVersion) + " (" + kGitDescribe + ")";
  m.command_line = MpiSession::commandLine();
  m.ranks = comm.size();
  m.launch_ranks = MpiSession::worldSize();
  // This program's world ranks: contiguous in an MPMD launch (mpirun's order of the programs).
  const int first = -comm.max(-MpiSession::worldRank()), last = comm.max(MpiSession::worldRank());
  m.rank_layout = program + ": " + (m.ranks == 1 ? "1 rank" : std::to_string(m.ranks) + " ranks");
  if (m.launch_ranks != m.ranks)
    m.rank_layout += " (world " + (first == last ? "rank " + std::to_string(first)
                                                 : "ranks " + std::to_string(first) + "-" + std::to_string(last)) +
                     " of a " + std::to_string(m.launch_ranks) + "-rank launch)";
  char host[256] = {0};
  gethostname(host, sizeof host - 1);
  m.host = host;
  m.started = utcNow();
  m.scene_file = scene.file;
  m.scene_hash = sceneHash(scene);
  m.scene_as_understood = dumpScene(scene);
  eachString(m, [&](const char*, std::string& v) {
    v = fromRoot(comm, v);
    if (v == std::string(1, '\0')) v.clear();
  });
  return m;
}

void RunMetadata::writeTo(const H5Group& g) const {
  eachString(*this, [&](const char* name, const std::string& v) { g.writeAttribute(name, v); });
  g.writeAttribute("ranks", std::vector<std::int64_t>{ranks});
  g.writeAttribute("launch_ranks", std::vector<std::int64_t>{launch_ranks});
}

RunMetadata RunMetadata::readFrom(const H5Group& g) {
  RunMetadata m;
  eachString(m, [&](const char* name, std::string& v) { v = g.readAttributeString(name); });
  m.ranks = g.readAttributeInt("ranks").at(0);
  m.launch_ranks = g.readAttributeInt("launch_ranks").at(0);
  return m;
}

const RunMetadata* RunMetadata::current() { return published(); }
void RunMetadata::publish(const RunMetadata* m) { published() = m; }

}  // namespace mpmice::core
