#include "core/scene/scene.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace mpmice::core {

double ModelSpec::get(const std::string& key) const {
  const auto it = params.find(key);
  if (it == params.end())
    throw std::out_of_range("model '" + type + "' has no parameter '" + key + "'");
  return it->second;
}

double ModelSpec::get(const std::string& key, double fallback) const {
  const auto it = params.find(key);
  return it == params.end() ? fallback : it->second;
}

const MaterialSpec* Scene::material(const std::string& n) const {
  const int i = materialIndex(n);
  return i < 0 ? nullptr : &materials[static_cast<std::size_t>(i)];
}

int Scene::materialIndex(const std::string& n) const {
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i].name == n) return static_cast<int>(i);
  return -1;
}

std::vector<int> Scene::solids() const {
  std::vector<int> out;
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i].kind == MaterialKind::Solid) out.push_back(static_cast<int>(i));
  return out;
}

std::vector<int> Scene::fluids() const {
  std::vector<int> out;
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i].kind == MaterialKind::Fluid) out.push_back(static_cast<int>(i));
  return out;
}

std::array<bool, 3> Scene::periodic() const {
  std::array<bool, 3> p{false, false, false};
  for (int d = 0; d < 3; ++d)
    p[d] = boundary[2 * d].type == BoundaryType::Periodic && boundary[2 * d + 1].type == BoundaryType::Periodic;
  return p;
}

const char* boundaryFaceName(int face) {
  static const char* names[] = {"x-", "x+", "y-", "y+", "z-", "z+"};
  return face >= 0 && face < 6 ? names[face] : "?";
}

const char* toString(BoundaryType t) {
  switch (t) {
    case BoundaryType::Symmetry: return "symmetry";
    case BoundaryType::SlipWall: return "slip_wall";
    case BoundaryType::NoSlipWall: return "noslip_wall";
    case BoundaryType::Inflow: return "inflow";
    case BoundaryType::Outflow: return "outflow";
    case BoundaryType::Periodic: return "periodic";
    case BoundaryType::Free: return "free";
  }
  return "?";
}

Scene loadScene(const std::string& path) {
  SourceLoc where;
  where.file = path;
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw SceneError(where, "", "'" + path + "' is a directory; expected a scene file (YAML)");
  std::ifstream in(path, std::ios::binary);
  if (!in.is_open() || !in)
    throw SceneError(where, "", "cannot open the scene file (does '" + path + "' exist and is it readable?)");
  std::ostringstream text;
  text << in.rdbuf();
  return parseScene(text.str(), path);
}

}  // namespace mpmice::core
