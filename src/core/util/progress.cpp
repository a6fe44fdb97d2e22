#include "core/util/progress.h"

#include <chrono>
#include <cstdio>

namespace mpmice::core {

namespace {
double steadySeconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
}  // namespace

Progress::Progress(std::ostream& os, const Comm& comm, double tStart, double tEnd, ProgressOptions opts, Clock clock)
    : os_(os), printer_(comm.root()), tStart_(tStart), tEnd_(tEnd), opts_(opts),
      clock_(clock ? std::move(clock) : Clock(steadySeconds)) {
  if (printer_) wallStart_ = lastPrint_ = clock_();
}

void Progress::start(const std::string& scene, const std::string& meshDescription, int ranks) {
  if (!printer_) return;
  wallStart_ = lastPrint_ = clock_();
  os_ << "scene " << scene << ": " << meshDescription << ", " << ranks << (ranks == 1 ? " rank" : " ranks")
      << ", t = " << fmt("%.3e", tStart_) << " .. " << fmt("%.3e", tEnd_) << " s\n"
      << std::flush;
}

double Progress::fractionDone(double t, double tStart, double tEnd, long step, long maxSteps, long stepStart) {
  const double span = tEnd - tStart;
  double done = span > 0 ? (t - tStart) / span : 1.0;
  if (maxSteps > stepStart) {
    const double bySteps = double(step - stepStart) / double(maxSteps - stepStart);
    if (bySteps > done) done = bySteps;
  }
  return done < 0 ? 0.0 : done > 1 ? 1.0 : done;
}

double Progress::etaFromFraction(double done, double wall) {
  if (!(done > 0)) return -1.0;
  return done < 1 ? wall * (1.0 - done) / done : 0.0;
}

double Progress::eta(double t, double tStart, double tEnd, double wall) {
  if (!(t > tStart)) return -1.0;
  return etaFromFraction(fractionDone(t, tStart, tEnd), wall);
}

std::string Progress::formatLine(int step, double t, double tStart, double tEnd, double dt, double wall,
                                 const Extras& extras, long maxSteps, long stepStart, const std::string& tail) {
  const double done = fractionDone(t, tStart, tEnd, step, maxSteps, stepStart);
  std::string s = "step " + std::to_string(step) + "  t = " + fmt("%.3e", t) + " / " + fmt("%.3e", tEnd) +
                  " s (" + fmt("%.1f", 100.0 * done) + "%)  dt = " + fmt("%.1e", dt) + "  wall " +
                  fmt("%.1f", wall) + " s";
  const double e = etaFromFraction(done, wall);
  s += e >= 0 ? "  ETA " + fmt("%.1f", e) + " s" : std::string("  ETA --");
  for (const auto& [key, value] : extras) s += "  " + key + "=" + fmt("%g", value);
  if (!tail.empty()) s += "  " + tail;
  return s;
}

bool Progress::step(int step, double t, double dt, const Extras& extras, bool force, const std::string& tail) {
  if (!printer_) return false;
  const double now = clock_();
  const bool bySteps = opts_.everySteps > 0 && step % opts_.everySteps == 0;
  const bool byTime = opts_.everySeconds > 0 && now - lastPrint_ >= opts_.everySeconds;
  const bool always = opts_.everySteps <= 0 && opts_.everySeconds <= 0;
  if (!(force || bySteps || byTime || always)) return false;
  lastPrint_ = now;
  os_ << formatLine(step, t, tStart_, tEnd_, dt, now - wallStart_, extras, opts_.maxSteps, opts_.stepStart, tail)
      << '\n' << std::flush;
  return true;
}

void Progress::finish(int steps, double t, double workPerStep, const std::string& workUnit) {
  if (!printer_) return;
  const double wall = clock_() - wallStart_;
  os_ << "done: " << steps << (steps == 1 ? " step" : " steps") << ", t = " << fmt("%.3e", t) << " s, wall "
      << fmt("%.1f", wall) << " s";
  if (wall > 0) {
    os_ << ", " << fmt("%.3g", steps / wall) << " steps/s";
    if (workPerStep > 0) os_ << ", " << fmt("%.3e", workPerStep * steps / wall) << " " << workUnit << "/s";
  }
  os_ << '\n' << std::flush;
}

double Progress::elapsed() const { return printer_ ? clock_() - wallStart_ : 0.0; }

}  // namespace mpmice::core
