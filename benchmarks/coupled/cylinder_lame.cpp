// cylinder_lame: the seed's validation measure for a finished pressurized-cylinder run.
//
// Sample run:   cylinder_lame output/pressurized_cylinder [plot-prefix]
// Reads the last output step of a coupled run (mpmice: <dir>/<scene>_NNNNNN.h5; MPMD:
// <dir>/<scene>_solid_NNNNNN.h5 + <dir>/<scene>_fluid_NNNNNN.h5), takes P as the mean pressure of
// the cells with r < 0.8 r_i, and prints the Eq. 13 error: the particle average of
// |(sigma_r + sigma_theta) - 2 P r_i^2 / (r_o^2 - r_i^2)| / (2 P r_i^2 / (r_o^2 - r_i^2)).
// With a plot prefix it writes <prefix>.csv (the particles nearest the x-axis: r, sigma_r,
// sigma_theta and the Lame values) and <prefix>.png through gnuplot.
// 1. Find the last step's files.  2. Read P.  3. Particle stresses -> error.  4. Profile + plot.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <string>

#include "core/io/output_reader.h"

namespace fs = std::filesystem;
using mpmice::core::Centering;
using mpmice::core::OutputReader;

namespace {
constexpr double kRi = 0.5, kRo = 1.0;

std::string lastFile(const fs::path& dir, const std::string& pattern) {
  const std::regex re(pattern);
  std::string best;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string n = e.path().filename().string();
    if (std::regex_match(n, re) && n > best) best = n;
  }
  return best.empty() ? "" : (dir / best).string();
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: cylinder_lame <output-dir>/<scene> [plot-prefix]\n";
    return 2;
  }
  try {
    // 1. Files.
    const fs::path base(argv[1]);
    const fs::path dir = base.parent_path().empty() ? fs::path(".") : base.parent_path();
    const std::string scene = base.filename().string();
    std::string parts = lastFile(dir, scene + "_[0-9]+\\.h5"), grid = parts;
    if (parts.empty()) {
      parts = lastFile(dir, scene + "_solid_[0-9]+\\.h5");
      grid = lastFile(dir, scene + "_fluid_[0-9]+\\.h5");
    }
    if (parts.empty() || grid.empty())
      throw std::runtime_error("no output of scene '" + scene + "' in " + dir.string());
    const OutputReader pr(parts), gr(grid);
    // 2. P: mean pressure of the cells well inside the inner radius.
    const auto mesh = gr.mesh();
    const auto p = gr.readGridField(Centering::Cell, "pressure");
    double psum = 0;
    long pn = 0;
    for (int j = 0; j < mesh.cells()[1]; ++j)
      for (int i = 0; i < mesh.cells()[0]; ++i)
        if (std::hypot(mesh.cellCenter(0, i), mesh.cellCenter(1, j)) < 0.8 * kRi) {
          psum += p.values[static_cast<std::size_t>(i + mesh.cells()[0] * j)];
          ++pn;
        }
    const double P = psum / double(pn);
    const double A = P * kRi * kRi / (kRo * kRo - kRi * kRi), sum = 2 * A;
    // 3. Particles.
    const auto x = pr.readParticleArray("position"), s = pr.readParticleArray("stress");
    const auto n = static_cast<std::size_t>(x.shape[0]);
    const auto sc = static_cast<std::size_t>(s.shape.size() > 1 ? s.shape[1] : 1);
    double err = 0;
    for (std::size_t q = 0; q < n; ++q) err += std::abs(s.values[sc * q] + s.values[sc * q + 1] - sum) / sum;
    err /= double(n);
    std::printf("cylinder_lame: %s step %d t = %.4g s, dx = %g, %zu particles, P = %.5g Pa, 2P/3 = %.5g Pa, "
                "Eq. 13 error = %.4g\n", parts.c_str(), pr.step(), pr.time(), mesh.dx(0), n, P, sum, err);
    // 4. Profile near the x-axis and plot.
    if (argc > 2) {
      const std::string prefix = argv[2];
      std::ofstream csv(prefix + ".csv");
      csv << "r,sigma_r,sigma_theta,lame_sigma_r,lame_sigma_theta\n";
      for (std::size_t q = 0; q < n; ++q) {
        const double px = x.values[3 * q], py = x.values[3 * q + 1];
        if (py > 0.5 * mesh.dx(1)) continue;
        const double r = std::hypot(px, py), c = px / r, sn = py / r;
        const double sxx = s.values[sc * q], syy = s.values[sc * q + 1], sxy = s.values[sc * q + 3];
        const double sr = sxx * c * c + syy * sn * sn + 2 * sxy * sn * c;
        const double st = sxx * sn * sn + syy * c * c - 2 * sxy * sn * c;
        const double B = A * kRo * kRo;
        csv << r << ',' << sr << ',' << st << ',' << A - B / (r * r) << ',' << A + B / (r * r) << '\n';
      }
      csv.close();
      std::ofstream gp(prefix + ".gp");
      gp << "set terminal png size 800,560\nset output '" << prefix << ".png'\nset datafile separator ','\n"
         << "set key top right\nset xlabel 'r [m]'\nset ylabel 'stress [MPa]'\nset grid\n"
         << "set title 'Pressurized cylinder, MPM-ICE, dx = " << mesh.dx(0) << " m: particles nearest y = 0'\n"
         << "set xrange [0.5:1.0]\nA = " << A / 1e6 << "\nB = " << A * kRo * kRo / 1e6 << "\n"
         << "plot '" << prefix << ".csv' every ::1 using 1:($3/1e6) with points pt 7 ps 0.8 title 'hoop, MPM-ICE', \\\n"
         << "  '' every ::1 using 1:($2/1e6) with points pt 5 ps 0.8 title 'radial, MPM-ICE', \\\n"
         << "  A + B/x**2 with lines lw 2 title 'hoop, Lame', A - B/x**2 with lines lw 2 title 'radial, Lame'\n";
      gp.close();
      const std::string cmd = "gnuplot '" + prefix + ".gp'";
      if (std::system(cmd.c_str()) != 0) std::cerr << "cylinder_lame: gnuplot failed; the CSV is written\n";
      else std::printf("cylinder_lame: wrote %s.csv and %s.png\n", prefix.c_str(), prefix.c_str());
    }
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "cylinder_lame: " << e.what() << "\n";
    return 1;
  }
}
