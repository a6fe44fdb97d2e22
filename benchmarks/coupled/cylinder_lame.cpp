// cylinder_lame: the seed's validation measure for a finished pressurized-cylinder run.
//
// Sample run:   cylinder_lame output/pressurized_cylinder [plot-prefix] --scene configs/pressurized_cylinder.yaml
// Reads the last output step of a coupled run (mpmice: <dir>/<scene>_NNNNNN.h5; MPMD:
// <dir>/<scene>_solid_NNNNNN.h5 + <dir>/<scene>_fluid_NNNNNN.h5), takes P as the mean pressure of
// the cells with r < 0.8 r_i, and prints the Eq. 13 error: the particle average of
// |(sigma_r + sigma_theta) - S| / S with the exact Lame sum
//   S = 2 ((P - p_ref) r_i^2 - (p_amb - p_ref) r_o^2) / (r_o^2 - r_i^2)
// for the stress measured from the solid's stress-free reference at p_ref (its EOS's
// threshold_pressure) with the ambient pressure p_amb outside. With --scene the radii come from
// the solid's annulus, p_amb from the outflow boundary pressure (else the fluid region outside
// the annulus) and p_ref from the solid; without it, the seed's legacy measure (r_i 0.5, r_o 1.0,
// S = 2 P r_i^2 / (r_o^2 - r_i^2) with the absolute P: the figures of docs/coupling.md).
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
#include <vector>

#include "core/io/output_reader.h"
#include "core/scene/scene.h"

namespace fs = std::filesystem;
using mpmice::core::Centering;
using mpmice::core::OutputReader;

namespace {

/// What the exact solution needs from the scene.
struct Annulus {
  double ri = 0.5, ro = 1.0, pAmbient = 0, pRef = 0;  // legacy: the seed, absolute pressure
  bool fromScene = false;
};

Annulus fromScene(const std::string& file) {
  const mpmice::core::Scene s = mpmice::core::loadScene(file);
  Annulus a;
  a.fromScene = true;
  int solid = -1;
  for (const auto& r : s.geometry)
    for (const auto& f : r.fill)
      if (s.material(f.material)->kind == mpmice::core::MaterialKind::Solid && r.shape.type == "annulus") {
        a.ri = r.shape.inner_radius;
        a.ro = r.shape.outer_radius;
        solid = s.materialIndex(f.material);
      }
  if (solid < 0) throw std::runtime_error(file + ": no solid annulus in the geometry");
  a.pRef = s.materials[static_cast<std::size_t>(solid)].eos.get("threshold_pressure", 101325.0);
  a.pAmbient = -1;
  for (const auto& b : s.boundary)
    if (b.type == mpmice::core::BoundaryType::Outflow && b.pressure) a.pAmbient = *b.pressure;
  if (a.pAmbient < 0)
    for (const auto& r : s.geometry)
      if (r.shape.type != "annulus" && s.material(r.fill.at(0).material)->kind == mpmice::core::MaterialKind::Fluid &&
          r.pressure)
        a.pAmbient = *r.pressure;
  if (a.pAmbient < 0) throw std::runtime_error(file + ": no outflow boundary or fluid region gives the ambient pressure");
  return a;
}

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
  std::vector<std::string> args(argv + 1, argv + argc);
  Annulus geo;
  try {
    for (std::size_t i = 0; i < args.size(); ++i)
      if (args[i] == "--scene" && i + 1 < args.size()) {
        geo = fromScene(args[i + 1]);
        args.erase(args.begin() + static_cast<long>(i), args.begin() + static_cast<long>(i) + 2);
        break;
      }
  } catch (const std::exception& e) {
    std::cerr << "cylinder_lame: " << e.what() << "\n";
    return 2;
  }
  if (args.empty()) {
    std::cerr << "usage: cylinder_lame <output-dir>/<scene> [plot-prefix] [--scene scene.yaml]\n";
    return 2;
  }
  const double kRi = geo.ri, kRo = geo.ro;
  try {
    // 1. Files.
    const fs::path base(args[0]);
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
    // Lame: sigma_r = A - B / r^2, sigma_theta = A + B / r^2 (from the stress-free reference).
    const double A = ((P - geo.pRef) * kRi * kRi - (geo.pAmbient - geo.pRef) * kRo * kRo) / (kRo * kRo - kRi * kRi);
    const double B = (P - geo.pAmbient) * kRi * kRi * kRo * kRo / (kRo * kRo - kRi * kRi), sum = 2 * A;
    // 3. Particles.
    const auto x = pr.readParticleArray("position"), s = pr.readParticleArray("stress");
    const auto n = static_cast<std::size_t>(x.shape[0]);
    const auto sc = static_cast<std::size_t>(s.shape.size() > 1 ? s.shape[1] : 1);
    // The error by band: particles within one cell of either surface, and the interior.
    double err = 0, errBand = 0, errCore = 0;
    std::size_t nBand = 0;
    for (std::size_t q = 0; q < n; ++q) {
      const double e = std::abs(s.values[sc * q] + s.values[sc * q + 1] - sum) / sum;
      const double r = std::hypot(x.values[3 * q], x.values[3 * q + 1]);
      err += e;
      if (r < kRi + mesh.dx(0) || r > kRo - mesh.dx(0)) {
        errBand += e;
        ++nBand;
      } else {
        errCore += e;
      }
    }
    err /= double(n);
    std::printf("cylinder_lame: %s step %d t = %.4g s, dx = %g, %zu particles, P = %.5g Pa, exact sum %.5g Pa "
                "(%s), Eq. 13 error = %.4g\n", parts.c_str(), pr.step(), pr.time(), mesh.dx(0), n, P, sum,
                geo.fromScene ? "r_i, r_o, p_amb, p_ref from the scene" : "legacy: seed radii, absolute P", err);
    std::printf("cylinder_lame: within one cell of a surface: %zu particles, mean error %.4g (%.0f %% of the sum); "
                "interior: %zu particles, mean error %.4g\n", nBand, nBand ? errBand / double(nBand) : 0.0,
                err > 0 ? 100.0 * errBand / (err * double(n)) : 0.0, n - nBand,
                n > nBand ? errCore / double(n - nBand) : 0.0);
    // 4. Profile near the x-axis and plot.
    if (args.size() > 1) {
      const std::string prefix = args[1];
      std::ofstream csv(prefix + ".csv");
      csv << "r,sigma_r,sigma_theta,lame_sigma_r,lame_sigma_theta\n";
      for (std::size_t q = 0; q < n; ++q) {
        const double px = x.values[3 * q], py = x.values[3 * q + 1];
        if (py > 0.5 * mesh.dx(1)) continue;
        const double r = std::hypot(px, py), c = px / r, sn = py / r;
        const double sxx = s.values[sc * q], syy = s.values[sc * q + 1], sxy = s.values[sc * q + 3];
        const double sr = sxx * c * c + syy * sn * sn + 2 * sxy * sn * c;
        const double st = sxx * sn * sn + syy * c * c - 2 * sxy * sn * c;
        csv << r << ',' << sr << ',' << st << ',' << A - B / (r * r) << ',' << A + B / (r * r) << '\n';
      }
      csv.close();
      std::ofstream gp(prefix + ".gp");
      gp << "set terminal png size 800,560\nset output '" << prefix << ".png'\nset datafile separator ','\n"
         << "set key top right\nset xlabel 'r [m]'\nset ylabel 'stress [MPa]'\nset grid\n"
         << "set title 'Pressurized cylinder, MPM-ICE, dx = " << mesh.dx(0) << " m: particles nearest y = 0'\n"
         << "set xrange [" << kRi << ":" << kRo << "]\nA = " << A / 1e6 << "\nB = " << B / 1e6 << "\n"
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
