// ice_sod_l1: L1 density error of a 1D Sod profile at t = 0.2 on [0, 1] against the exact
// Riemann solution (tests/verification/ice/riemann_exact.h).
//   ice_sod_l1 --ice  run_000123.h5         (ice_solver output: sums every *_density field)
//   ice_sod_l1 --foam case/0.2/rho          (OpenFOAM volScalarField, uniform cells on [0, 1])
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "core/io/output_reader.h"
#include "riemann_exact.h"

namespace {

std::vector<double> readFoam(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::string line;
  while (std::getline(in, line) && line.find("internalField") == std::string::npos) {
  }
  std::size_t n = 0;
  in >> n;
  char paren;
  in >> paren;
  std::vector<double> v(n);
  for (auto& x : v) in >> x;
  if (!in) throw std::runtime_error("cannot read the internalField of " + path);
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: ice_sod_l1 --ice file.h5 | --foam rhoFile\n";
    return 2;
  }
  try {
    const std::string mode = argv[1], path = argv[2];
    std::vector<double> rho;
    double t = 0.2;
    if (mode == "--ice") {
      mpmice::core::OutputReader r(path);
      t = r.time();
      for (const auto& name : r.gridFieldNames(mpmice::core::Centering::Cell)) {
        if (name.size() < 8 || name.substr(name.size() - 8) != "_density") continue;
        const auto a = r.readGridField(mpmice::core::Centering::Cell, name);
        if (rho.empty()) rho.assign(a.values.size(), 0.0);
        for (std::size_t i = 0; i < a.values.size(); ++i) rho[i] += a.values[i];
      }
    } else if (mode == "--foam") {
      rho = readFoam(path);
    } else {
      throw std::runtime_error("unknown mode " + mode);
    }
    if (rho.empty()) throw std::runtime_error("no density in " + path);
    const mpmice::test::ExactRiemann ex({1, 0, 1}, {0.125, 0, 0.1});
    const double dx = 1.0 / double(rho.size());
    double err = 0;
    for (std::size_t i = 0; i < rho.size(); ++i) {
      const double x = (double(i) + 0.5) * dx;
      err += std::abs(rho[i] - ex.sample((x - 0.5) / t).rho) * dx;
    }
    std::printf("%.6e\n", err);
  } catch (const std::exception& e) {
    std::cerr << "ice_sod_l1: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
