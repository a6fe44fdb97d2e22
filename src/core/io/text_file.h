#pragma once
/// @brief The whole text of a file (empty when it cannot be read).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace mpmice::core {

inline std::string readTextFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace mpmice::core
