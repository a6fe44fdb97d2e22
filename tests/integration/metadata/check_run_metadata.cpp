// check_run_metadata RUN_YAML PROGRAM RANK_LAYOUT FILE.h5...: every file's root attributes describe
// the run as its run record does (core/io/run_metadata.h), value for value; prints one line per
// file, "FAIL: ..." and exit 1 on the first difference.
#include <iostream>
#include <string>
#include <yaml-cpp/yaml.h>

#include "core/io/h5_file.h"
#include "core/io/run_metadata.h"
#include "core/parallel/mpi_session.h"

using namespace mpmice::core;

namespace {
std::string trimmed(std::string s) {
  while (!s.empty() && s.back() == '\n') s.pop_back();
  return s;
}
}  // namespace

int main(int argc, char** argv) {
  MpiSession session(argc, argv);
  if (argc < 5) {
    std::cerr << "usage: check_run_metadata RUN_YAML PROGRAM RANK_LAYOUT FILE.h5...\n";
    return 2;
  }
  const YAML::Node rec = YAML::LoadFile(argv[1]);
  const std::string program = argv[2], layout = argv[3];
  int bad = 0;
  auto expect = [&](const std::string& file, const std::string& key, const std::string& got, const std::string& want) {
    if (got == want) return;
    std::cout << "FAIL: " << file << ": attribute " << key << " is '" << got << "', expected '" << want << "'\n";
    ++bad;
  };
  for (int i = 4; i < argc; ++i) {
    const std::string f = argv[i];
    const RunMetadata m = RunMetadata::readFrom(H5File::open(f).root());
    expect(f, "program", m.program, program);
    expect(f, "rank_layout", m.rank_layout, layout);
    for (const auto& [key, value] : {std::pair<std::string, std::string>{"program", m.program},
                                     {"version", m.version},
                                     {"command_line", m.command_line},
                                     {"rank_layout", m.rank_layout},
                                     {"host", m.host},
                                     {"started", m.started},
                                     {"scene_file", m.scene_file},
                                     {"scene_hash", m.scene_hash},
                                     {"ranks", std::to_string(m.ranks)},
                                     {"launch_ranks", std::to_string(m.launch_ranks)}})
      expect(f, key, value, rec[key].as<std::string>());
    expect(f, "scene_as_understood", trimmed(m.scene_as_understood), trimmed(rec["scene_as_understood"].as<std::string>()));
    std::cout << f << ": " << m.program << " " << m.version << ", " << m.rank_layout << ", started " << m.started
              << ", scene " << m.scene_hash << "\n";
  }
  return bad ? 1 : 0;
}
