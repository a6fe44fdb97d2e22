#include "core/io/run_record.h"

#include <filesystem>
#include <fstream>
#include <sstream>


namespace mpmice::core {

namespace {
std::string yamlQuoted(const std::string& s) {
  std::string q = "\"";
  for (char c : s) q += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return q + "\"";
}
}  // namespace

RunRecord::RunRecord(const Scene& scene, const Comm& comm, std::string program, const std::string& suffix)
    : scene_(scene), writer_(scene.output.enabled && comm.root()), meta_(RunMetadata::describe(scene, comm, program)) {
  path_ = scene.output.directory + "/" + scene.name + suffix + "_run.yaml";
  RunMetadata::publish(&meta_);
  write("running");
}

RunRecord::~RunRecord() {
  if (RunMetadata::current() == &meta_) RunMetadata::publish(nullptr);
}

void RunRecord::completed() { write("completed"); }

void RunRecord::write(const std::string& status) const {
  if (!writer_) return;
  std::filesystem::create_directories(scene_.output.directory);
  std::ostringstream o;
  o << "# What this run was (src/core/io/run_record.h).\n"
    << "program: " << meta_.program << "\nversion: " << yamlQuoted(meta_.version)
    << "\ncommand_line: " << yamlQuoted(meta_.command_line) << "\nranks: " << meta_.ranks
    << "\nlaunch_ranks: " << meta_.launch_ranks << "\nrank_layout: " << yamlQuoted(meta_.rank_layout)
    << "\nhost: " << yamlQuoted(meta_.host) << "\nstarted: " << meta_.started
    << "\nended: " << (status == "running" ? std::string("null") : utcNow()) << "\nstatus: " << status
    << "\nscene_file: " << yamlQuoted(meta_.scene_file) << "\nscene_hash: " << meta_.scene_hash
    << "\nscene_as_understood: |\n";
  std::istringstream dump(meta_.scene_as_understood);
  for (std::string line; std::getline(dump, line);) o << "  " << line << "\n";
  const std::string tmp = path_ + ".part";
  {
    std::ofstream f(tmp);
    f << o.str();
  }
  std::filesystem::rename(tmp, path_);
}

}  // namespace mpmice::core
