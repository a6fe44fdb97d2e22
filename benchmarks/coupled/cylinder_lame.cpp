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
// --profile prints the radial profile in bins of dx / 2 (signed Eq. 13 bias, sigma_r, sigma_theta).
// With a plot prefix it writes <prefix>.csv (the particles nearest the x-axis: r, sigma_r,
// sigma_theta and the Lame values) and <prefix>.png through gnuplot. It first prints the gas leak:
// the fraction of the fluids' mass inside r_i at the first output step that is no longer inside
// r_i at the last (study/reference/lame_cylinder.h, gasLeak).
// 1. Find the last step's files.  2. Read P.  3. Particle stresses -> error.  4. Profile + plot.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "study/reference/lame_cylinder.h"

using mpmice::study::Annulus;

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  Annulus geo;
  bool profile = false;  // --profile: the radial profile in bins of dx / 2
  try {
    for (std::size_t i = 0; i < args.size(); ++i)
      if (args[i] == "--scene" && i + 1 < args.size()) {
        geo = mpmice::study::annulusFromScene(args[i + 1]);
        args.erase(args.begin() + static_cast<long>(i), args.begin() + static_cast<long>(i) + 2);
        break;
      }
    for (std::size_t i = 0; i < args.size(); ++i)
      if (args[i] == "--profile") {
        profile = true;
        args.erase(args.begin() + static_cast<long>(i));
        break;
      }
  } catch (const std::exception& e) {
    std::cerr << "cylinder_lame: " << e.what() << "\n";
    return 2;
  }
  if (args.empty()) {
    std::cerr << "usage: cylinder_lame <output-dir>/<scene> [plot-prefix] [--scene scene.yaml] [--profile]\n";
    return 2;
  }
  const double kRi = geo.ri, kRo = geo.ro;
  try {
    // 1. Files.  2. P.  3. Particles -> error (src/study/reference/lame_cylinder.h).
    const std::filesystem::path base(args[0]);
    const std::string dir = base.parent_path().empty() ? "." : base.parent_path().string();
    // 0. The gas leak through the wall (first to last output step; also for a run that stopped).
    const auto leak = mpmice::study::gasLeak(dir, base.filename().string(), geo);
    std::printf("cylinder_lame: gas inside r_i: %.6g kg (step %d, t = %.4g s) -> %.6g kg (step %d, t = %.4g s): "
                "leak %.4g of it; the gas in the wall's cells (r_i..r_o) %.6g -> %.6g kg (per unit depth)\n",
                leak.inside0, leak.firstStep, leak.firstTime, leak.inside, leak.lastStep, leak.lastTime,
                leak.fraction(), leak.wall0, leak.wall);
    const auto r = mpmice::study::lameError(dir, base.filename().string(), geo);
    const double A = r.A, B = r.B, err = r.error, dx = r.dx;
    const std::size_t n = r.particles, nBand = r.bandParticles, sc = r.stressComponents;
    std::printf("cylinder_lame: %s step %d t = %.4g s, dx = %g, %zu particles, P = %.5g Pa, exact sum %.5g Pa "
                "(%s), Eq. 13 error = %.4g\n", r.particlesFile.c_str(), r.step, r.time, dx, n, r.P, r.sum,
                geo.fromScene ? "r_i, r_o, p_amb, p_ref from the scene" : "legacy: seed radii, absolute P", err);
    std::printf("cylinder_lame: within one cell of a surface: %zu particles, mean error %.4g (%.0f %% of the sum); "
                "interior: %zu particles, mean error %.4g\n", nBand, nBand ? r.bandError / double(nBand) : 0.0,
                err > 0 ? 100.0 * r.bandError / (err * double(n)) : 0.0, n - nBand,
                n > nBand ? r.coreError / double(n - nBand) : 0.0);
    // 3b. The error by band as docs/mpm.md measures MPM alone (mpm_study lame_bands): Eq. 13 sum
    //     by distance from the nearer curved surface in cells, [0,1) [1,2) [2,4) [4,8) [8,...),
    //     and the signed means of the first cell at the inner and at the outer surface.
    {
      double acc[5] = {0, 0, 0, 0, 0}, sgn[5] = {0, 0, 0, 0, 0}, cnt[5] = {0, 0, 0, 0, 0}, sIn = 0, sOut = 0;
      std::size_t nIn = 0, nOut = 0;
      for (std::size_t q = 0; q < n; ++q) {
        const double rad = std::hypot(r.x[3 * q], r.x[3 * q + 1]);
        const double e = (r.stress[sc * q] + r.stress[sc * q + 1] - r.sum) / r.sum;
        const double t = std::min(rad - kRi, kRo - rad) / dx;
        const int bin = t < 1 ? 0 : t < 2 ? 1 : t < 4 ? 2 : t < 8 ? 3 : 4;
        acc[bin] += std::fabs(e);
        sgn[bin] += e;
        cnt[bin] += 1;
        if (rad - kRi < dx) sIn += e, ++nIn;
        if (kRo - rad < dx) sOut += e, ++nOut;
      }
      const double N = double(n);
      std::printf("cylinder_lame: bands | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | (total, 0-1, 1-2, 2-4, 4-8, >=8 dx); "
                  "signed mean 0-1 dx inner %+.4f (%zu), outer %+.4f (%zu)\n", err, acc[0] / N, acc[1] / N, acc[2] / N,
                  acc[3] / N, acc[4] / N, nIn ? sIn / double(nIn) : 0.0, nIn, nOut ? sOut / double(nOut) : 0.0, nOut);
      std::printf("cylinder_lame: signed mean per particle by band (0-1, 1-2, 2-4, 4-8, >=8 dx):");
      for (int k = 0; k < 5; ++k) std::printf(" %+.4f", cnt[k] > 0 ? sgn[k] / cnt[k] : 0.0);
      std::printf("\n");
    }
    // 3c. --profile: by radius in bins of dx / 2 over all particles, the signed mean of
    //     ((sigma_r + sigma_theta) - S) / S and the means of sigma_r and sigma_theta against Lame's
    //     at the bin's mean radius (as `mpm_study lame_bands` prints MPM alone's with LAME_PROFILE=1).
    if (profile) {
      const double h = 0.5 * dx;
      const int nb = static_cast<int>(std::ceil((kRo - kRi) / h)) + 2;
      std::vector<double> c(nb, 0), e(nb, 0), ea(nb, 0), rr(nb, 0), srs(nb, 0), sts(nb, 0);
      double ac[9] = {}, ae[9] = {}, aa[9] = {};  // interior (>= 2 dx from both surfaces) by angle, 10 degrees each
      for (std::size_t q = 0; q < n; ++q) {
        const double px = r.x[3 * q], py = r.x[3 * q + 1], rad = std::hypot(px, py), cs = px / rad, sn = py / rad;
        const int b = std::clamp(static_cast<int>(std::floor((rad - kRi) / h)) + 1, 0, nb - 1);
        const double sxx = r.stress[sc * q], syy = r.stress[sc * q + 1], sxy = r.stress[sc * q + 3];
        c[b] += 1;
        const double eq = (sxx + syy - r.sum) / r.sum;
        e[b] += eq;
        ea[b] += std::fabs(eq);
        if (std::min(rad - kRi, kRo - rad) >= 2 * dx) {
          const int k = std::clamp(static_cast<int>(std::atan2(py, px) / (M_PI / 18)), 0, 8);
          ac[k] += 1, ae[k] += eq, aa[k] += std::fabs(eq);
        }
        rr[b] += rad;
        srs[b] += sxx * cs * cs + syy * sn * sn + 2 * sxy * sn * cs;
        sts[b] += sxx * sn * sn + syy * cs * cs - 2 * sxy * sn * cs;
      }
      std::printf("cylinder_lame: profile | r [m] | particles | signed (sum - S) / S | mean abs | sigma_r [MPa] | Lame | sigma_theta [MPa] | Lame |\n");
      for (int b = 0; b < nb; ++b) {
        if (c[b] == 0) continue;
        const double rm = rr[b] / c[b];
        std::printf("cylinder_lame: profile | %.5f | %.0f | %+.5f | %.5f | %.4f | %.4f | %.4f | %.4f |\n", rm, c[b], e[b] / c[b],
                    ea[b] / c[b], srs[b] / c[b] / 1e6, (A - B / (rm * rm)) / 1e6, sts[b] / c[b] / 1e6, (A + B / (rm * rm)) / 1e6);
      }
      std::printf("cylinder_lame: interior (>= 2 dx from both surfaces) by angle, 10 degree bins: signed / mean abs:");
      for (int k = 0; k < 9; ++k) std::printf(" %+.4f/%.4f", ac[k] > 0 ? ae[k] / ac[k] : 0.0, ac[k] > 0 ? aa[k] / ac[k] : 0.0);
      std::printf("\n");
    }
    // 4. Profile near the x-axis and plot.
    if (args.size() > 1) {
      const std::string prefix = args[1];
      std::ofstream csv(prefix + ".csv");
      csv << "r,sigma_r,sigma_theta,lame_sigma_r,lame_sigma_theta\n";
      for (std::size_t q = 0; q < n; ++q) {
        const double px = r.x[3 * q], py = r.x[3 * q + 1];
        if (py > 0.5 * dx) continue;
        const double rad = std::hypot(px, py), c = px / rad, sn = py / rad;
        const double sxx = r.stress[sc * q], syy = r.stress[sc * q + 1], sxy = r.stress[sc * q + 3];
        const double sr = sxx * c * c + syy * sn * sn + 2 * sxy * sn * c;
        const double st = sxx * sn * sn + syy * c * c - 2 * sxy * sn * c;
        csv << rad << ',' << sr << ',' << st << ',' << A - B / (rad * rad) << ',' << A + B / (rad * rad) << '\n';
      }
      csv.close();
      std::ofstream gp(prefix + ".gp");
      gp << "set terminal png size 800,560\nset output '" << prefix << ".png'\nset datafile separator ','\n"
         << "set key top right\nset xlabel 'r [m]'\nset ylabel 'stress [MPa]'\nset grid\n"
         << "set title 'Pressurized cylinder, MPM-ICE, dx = " << dx << " m: particles nearest y = 0'\n"
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
