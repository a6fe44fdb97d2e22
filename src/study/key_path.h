#pragma once
/// @brief Scene key paths: `mesh.spacing`, `mpm.shape_function`, `coupling.acceleration`,
/// `geometry[wall].particles_per_cell` (a list element chosen by its `name`, or by its index:
/// `geometry[1].particles_per_cell`). The study tool sets one value per path in a copy of the
/// base scene.
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace mpmice::study {

/// A bad key path, or one that does not fit the scene: what() names the path and the reason.
class KeyPathError : public std::runtime_error {
 public:
  KeyPathError(const std::string& path, const std::string& why);
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// One step of a path: a mapping key, then optionally a list element ([name] or [index]).
struct KeyStep {
  std::string key;
  std::optional<std::string> select;
};

/// Splits `path` into steps; throws KeyPathError on an empty step, an unclosed or empty [...].
std::vector<KeyStep> parseKeyPath(const std::string& path);

/// Sets `value` at `path` in `root` (a mapping). Absent mapping keys are created (the scene's
/// schema then judges them); a step through a scalar, a [...] on something that is not a list,
/// or a [name] no element carries is a KeyPathError naming the path and what is there.
void setKeyPath(YAML::Node root, const std::string& path, const YAML::Node& value);

}  // namespace mpmice::study
