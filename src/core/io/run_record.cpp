#include "core/io/run_record.h"

#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "core/parallel/mpi_session.h"
#include "core/version.h"

namespace mpmice::core {

namespace {
std::string utcNow() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char b[32];
  std::strftime(b, sizeof b, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return b;
}
std::string yamlQuoted(const std::string& s) {
  std::string q = "\"";
  for (char c : s) q += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return q + "\"";
}
}  // namespace

RunRecord::RunRecord(const Scene& scene, const Comm& comm, std::string program, const std::string& suffix)
    : scene_(scene), writer_(scene.output.enabled && comm.root()), program_(std::move(program)), ranks_(comm.size()) {
  path_ = scene.output.directory + "/" + scene.name + suffix + "_run.yaml";
  started_ = utcNow();
  write("running");
}

void RunRecord::completed() { write("completed"); }

void RunRecord::write(const std::string& status) const {
  if (!writer_) return;
  std::filesystem::create_directories(scene_.output.directory);
  char host[256] = {0};
  gethostname(host, sizeof host - 1);
  std::ostringstream o;
  o << "# What this run was (src/core/io/run_record.h).\n"
    << "program: " << program_ << "\nversion: " << yamlQuoted(std::string(kProjectVersion) + " (" + kGitDescribe + ")")
    << "\ncommand_line: " << yamlQuoted(MpiSession::commandLine()) << "\nranks: " << ranks_
    << "\nhost: " << yamlQuoted(host) << "\nstarted: " << started_
    << "\nended: " << (status == "running" ? std::string("null") : utcNow()) << "\nstatus: " << status
    << "\nscene_file: " << yamlQuoted(scene_.file) << "\nscene_hash: " << sceneHash(scene_)
    << "\nscene_as_understood: |\n";
  std::istringstream dump(dumpScene(scene_));
  for (std::string line; std::getline(dump, line);) o << "  " << line << "\n";
  const std::string tmp = path_ + ".part";
  {
    std::ofstream f(tmp);
    f << o.str();
  }
  std::filesystem::rename(tmp, path_);
}

}  // namespace mpmice::core
