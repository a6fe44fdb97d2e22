// Reads back what `mpm_solver mpm_output_block.yaml` wrote (run by run_mpm_output.sh through
// scripts/mpirun on 1 or 2 ranks) and checks it against the scene:
//   - one HDF5 file per output time (t = 0, 0.01, ..., 0.05: 6 files), the last at t = time.end;
//   - each holds the 128 particles of the block (8 x 4 cells, 2 x 2 per cell) with total mass
//     500 kg/m (1000 kg/m^3 * 1.0 m * 0.5 m), the listed particle arrays with their component
//     counts, and node mass / velocity on the 17 x 9 nodes; node mass sums to the particle mass;
//   - the XDMF index exists and names every step written (step_<step:06d>).
// Usage: mpm_output_block OUTPUT_DIR NRANKS
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/io/output_reader.h"

using mpmice::core::Centering;
using mpmice::core::OutputReader;

namespace {
int failures = 0;
void check(bool ok, const std::string& what) {
  std::printf("%s: %s\n", ok ? "ok  " : "FAIL", what.c_str());
  if (!ok) ++failures;
}
double sum(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return s;
}
}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: mpm_output_block OUTPUT_DIR NRANKS\n");
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  const int nranks = std::stoi(argv[2]);
  const long long kParticles = 128;  // 8 x 4 cells x 2 x 2
  const double kMass = 500.0;        // 1000 kg/m^3 x 1.0 m x 0.5 m
  const double kEnd = 0.05;
  const std::map<std::string, int> kArrays = {{"velocity", 3}, {"stress", 6}, {"deformation_gradient", 9},
                                              {"plastic_strain", 1}, {"mass", 1}, {"volume", 1},
                                              {"material", 1}, {"id", 1}};
  // 1. The step files, in step order.
  std::map<int, std::filesystem::path> steps;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".h5") {
      OutputReader r(e.path().string());
      steps[r.step()] = e.path();
    }
  check(steps.size() == 6, "6 output files (t = 0, 0.01, ..., 0.05), found " + std::to_string(steps.size()));
  // 2. Each file: particles, their mass, arrays, grid fields.
  double lastTime = -1;
  for (const auto& [step, path] : steps) {
    OutputReader r(path.string());
    const std::string tag = path.filename().string() + ": ";
    lastTime = r.time();
    check(r.numRanks() == nranks, tag + "written by " + std::to_string(r.numRanks()) + " ranks");
    check(r.hasParticles(), tag + "has particles");
    const auto mass = r.readParticleArray("mass");
    check(static_cast<long long>(mass.values.size()) == kParticles,
          tag + "particle count " + std::to_string(mass.values.size()) + " == 128");
    check(std::fabs(sum(mass.values) - kMass) < 1e-9 * kMass, tag + "total particle mass == 500");
    for (const auto& [name, nc] : kArrays) {
      const auto a = r.readParticleArray(name);
      const long long ncomp = a.shape.size() > 1 ? a.shape[1] : 1;
      check(a.shape[0] == kParticles && ncomp == nc, tag + name + " has " + std::to_string(nc) + " components");
    }
    const auto pos = r.readParticleArray("position");
    bool inside = true;
    for (long long i = 0; i < kParticles; ++i)
      inside = inside && pos.values[3 * i] > 0 && pos.values[3 * i] < 2 && pos.values[3 * i + 1] > 0 &&
               pos.values[3 * i + 1] < 1;
    check(inside, tag + "particles inside the mesh");
    const auto nm = r.readGridField(Centering::Node, "mass");
    check(nm.shape == std::vector<std::int64_t>({1, 9, 17}), tag + "node mass is (1, 9, 17)");
    check(std::fabs(sum(nm.values) - kMass) < 1e-9 * kMass, tag + "node mass sums to 500");
    const auto nv = r.readGridField(Centering::Node, "velocity");
    check(nv.shape.size() == 4 && nv.shape[3] == 3, tag + "node velocity has 3 components");
  }
  check(std::fabs(lastTime - kEnd) < 1e-12, "last step at time.end = 0.05");
  // 3. The XDMF index names every step.
  const auto xmf = dir / "mpm_output_block.xmf";
  check(std::filesystem::exists(xmf), "index " + xmf.string() + " exists");
  std::ifstream in(xmf);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  for (const auto& [step, path] : steps) {
    char name[32];
    std::snprintf(name, sizeof name, "step_%06d", step);
    check(text.find(std::string("Name=\"") + name + "\"") != std::string::npos &&
              text.find(path.filename().string()) != std::string::npos,
          std::string("index names ") + name + " and its file");
  }
  std::printf("%s\n", failures ? "FAILED" : "PASS");
  return failures ? 1 : 0;
}
