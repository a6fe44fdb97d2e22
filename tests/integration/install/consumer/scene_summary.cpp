// An installed mpmice through pkg-config (no CMake): read a scene, print what it holds.
//   c++ scene_summary.cpp $(pkg-config --cflags --libs mpmice) -o scene_summary
#include <iostream>

#include "core/scene/scene.h"
#include "core/version.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: scene_summary scene.yaml\n";
    return 2;
  }
  try {
    const auto scene = mpmice::core::loadScene(argv[1]);
    std::cout << "pkg-config consumer: " << mpmice::core::versionLine("scene_summary") << ": scene '" << scene.name
              << "', " << scene.solids().size() << " solid(s), " << scene.fluids().size() << " fluid(s)\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "scene_summary: " << e.what() << "\n";
    return 2;
  }
}
