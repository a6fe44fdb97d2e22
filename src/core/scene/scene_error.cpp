#include "core/scene/scene.h"

namespace mpmice::core {

std::string SourceLoc::str() const {
  std::string s = file.empty() ? std::string("<scene>") : file;
  if (line > 0) {
    s.append(1, ':').append(std::to_string(line));
    if (column > 0) s.append(1, ':').append(std::to_string(column));
  }
  return s;
}

namespace {
std::string composeMessage(const SourceLoc& where, const std::string& key, const std::string& what) {
  std::string msg = where.str() + ": ";
  // A key path is echoed whole up to 200 characters (a hostile key must not flood stderr).
  if (!key.empty()) msg += (key.size() <= 200 ? key : key.substr(0, 197) + "...") + ": ";
  return msg + what;
}
}  // namespace

SceneError::SceneError(const SourceLoc& where, const std::string& key, const std::string& what)
    : std::runtime_error(composeMessage(where, key, what)), where_(where), key_(key) {}

}  // namespace mpmice::core
