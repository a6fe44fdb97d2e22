#include "study/study_run.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "core/scene/scene.h"
#include "coupler/cli/process.h"
#include "coupler/cli/stop_signals.h"
#include "study/pareto.h"
#include "study/point_run.h"

namespace mpmice::study {

namespace fs = std::filesystem;

namespace {

std::string readText(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeText(const fs::path& p, const std::string& text) {
  std::ofstream o(p);
  o << text;
  if (!o) throw StudyError("cannot write " + p.string());
}

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) {
    if (c == '"') q.push_back('"');
    q.push_back(c == '\n' ? ' ' : c);
  }
  return q + "\"";
}

std::string num(double v, int digits = 6) {
  if (!std::isfinite(v)) return "nan";
  std::ostringstream o;
  o << std::setprecision(digits) << v;
  return o.str();
}

/// One point, prepared: its folder, its scene text.
struct Prepared {
  fs::path dir;
  std::string sceneText, sceneName;
};

}  // namespace

std::vector<std::string> pointCommand(const Study& s, const Point& p, const std::string& scene, const StudyOptions& o) {
  const std::string bin = o.binDir.empty() ? "." : o.binDir;
  if (s.program == Program::CouplerRun) return {bin + "/coupler/coupler", "run", "--bin-dir", bin, scene};
  const int ranks = pointRanks(p);
  if (ranks == 1) return {bin + "/coupler/mpmice", scene};
  return {o.mpirun, "-np", std::to_string(ranks), bin + "/coupler/mpmice", scene};
}

int runStudy(const Study& s, const StudyOptions& o, std::ostream& out, std::ostream& err) {
  const fs::path root = fs::absolute(o.out).lexically_normal();
  const Reference& ref = findReference(s.reference);
  YAML::Node base;
  try {
    base = YAML::LoadFile(s.scene);
  } catch (const YAML::Exception& e) {
    throw StudyError(s.file + ": 'scene': " + s.scene + " is not a readable YAML scene: " + e.what());
  }
  // 1. Every variant, checked by the scene schema before anything is created.
  std::vector<Prepared> prepared;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Point& p = s.points[i];
    Prepared pr;
    pr.dir = root / pointFolder(p, i + 1);
    YAML::Emitter e;
    e << variantScene(s, base, p, pr.dir.string());
    pr.sceneText = "# study " + s.name + ", point " + std::to_string(i + 1) + ": " + pointLabel(p) + "\n# base scene " +
                   s.scene + "\n" + e.c_str() + "\n";
    try {
      pr.sceneName = core::parseScene(pr.sceneText, (pr.dir / "scene.yaml").string()).name;
    } catch (const std::exception& ex) {
      std::string keys;
      for (const auto& [k, v] : p.settings) keys += (keys.empty() ? "" : ", ") + k + ": " + valueText(v);
      throw StudyError(s.file + ": point " + std::to_string(i + 1) + " (" + keys + ") gives an invalid scene: " + ex.what());
    }
    prepared.push_back(pr);
  }
  if (o.dryRun) {
    out << "study " << s.name << ": " << s.points.size() << " points, reference " << s.reference << ", time limit "
        << s.timeLimit << " s per run, into " << root.string() << "\n";
    for (std::size_t i = 0; i < s.points.size(); ++i)
      out << "  " << pointFolder(s.points[i], i + 1) << ": "
          << coupler::shellLine(pointCommand(s, s.points[i], (prepared[i].dir / "scene.yaml").string(), o)) << "\n";
    return 0;
  }
  // 2. The study folder: new, or (with --resume) one this tool made.
  const fs::path marker = root / (s.name + ".study.yaml");
  std::error_code ec;
  const bool exists = fs::exists(root, ec);
  if (exists && !fs::is_directory(root)) throw StudyError(root.string() + " exists and is not a folder");
  if (exists && !fs::is_empty(root)) {
    if (!o.resume)
      throw StudyError("the study folder " + root.string() +
                       " exists and is not empty: nothing is overwritten (give another --out, or --resume to "
                       "finish the study this tool started there)");
    if (!fs::is_regular_file(marker))
      throw StudyError("--resume: " + root.string() + " holds no " + marker.filename().string() +
                       ": it is not a folder this tool made for study " + s.name);
    if (readText(marker) != readText(s.file))
      throw StudyError("--resume: the study file " + s.file + " differs from the one that started " + root.string() +
                       " (" + marker.string() + ")");
  } else {
    fs::create_directories(root);
    writeText(marker, readText(s.file));
  }
  // 3. The points. SIGINT / SIGTERM go to the running point's process group; the study stops
  // after it, leaving that point without a result (--resume runs it again).
  const coupler::StopSignals signals;
  std::vector<PointResult> results;
  std::vector<TradePoint> trade;
  std::size_t ok = 0;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Prepared& pr = prepared[i];
    const fs::path sceneFile = pr.dir / "scene.yaml", resultFile = pr.dir / "result.yaml";
    const std::string label = pointLabel(s.points[i]);
    PointResult r;
    bool done = false;
    if (fs::exists(pr.dir)) {  // only with --resume (the folder was refused otherwise): a run this tool made
      if (fs::is_regular_file(sceneFile) && readText(sceneFile) != pr.sceneText)
        throw StudyError("--resume: " + sceneFile.string() + " is not the scene the study file gives for point " +
                         std::to_string(i + 1));
      if (fs::is_regular_file(resultFile)) {
        r = readResult(resultFile.string());
        done = r.status == "ok";
      }
      if (!done) fs::remove_all(pr.dir);
    }
    if (done) {
      out << "study " << s.name << ": point " << i + 1 << "/" << s.points.size() << " (" << label
          << "): finished before, skipped (error " << num(r.error, 4) << ", wall " << num(r.wallSeconds, 3) << " s, CPU "
          << num(r.cpuSeconds, 3) << " s)\n";
    } else {
      fs::create_directories(pr.dir);
      writeText(sceneFile, pr.sceneText);
      const auto argv = pointCommand(s, s.points[i], sceneFile.string(), o);
      writeText(pr.dir / "command.txt", coupler::shellLine(argv) + "\n");
      out << "study " << s.name << ": point " << i + 1 << "/" << s.points.size() << " (" << label << "): "
          << coupler::shellLine(argv) << std::endl;
      const RunFiles files{pr.dir.string(), sceneFile.string(), pr.sceneName, s.referenceCurve, s.referenceColumn};
      r = runPoint(argv, pr.dir.string(), s.timeLimit, s.repeats, ref, files);
      if (r.stoppedBy != 0) {
        err << "study " << s.name << ": stopped by " << coupler::signalName(r.stoppedBy) << " during point " << i + 1
            << " (no result written; --resume runs it again)\n";
        return 128 + r.stoppedBy;
      }
      writeText(resultFile, resultYaml(r));
      out << "  " << r.status << ": error " << num(r.error, 4) << ", wall " << num(r.wallSeconds, 3) << " s, CPU "
          << num(r.cpuSeconds, 3) << " s" << (r.walls.size() > 1 ? " (median of " + std::to_string(r.walls.size()) + ")" : "") << ", " << r.steps << " steps, " << num(r.iterationsPerStep, 3) << " iterations per step, peak RSS "
          << num(r.peakRssMb, 4) << " MB" << (r.note.empty() ? "" : " (" + r.note + ")") << std::endl;
    }
    if (r.status == "ok") ++ok;
    results.push_back(r);
    trade.push_back(TradePoint{label, s.cost == Cost::Cpu ? r.cpuSeconds : r.wallSeconds, r.error});
  }
  // 4. The CSV and the plot.
  const fs::path csv = root / (s.name + ".csv");
  {
    std::ostringstream c;
    c << "point";
    for (const auto& k : s.columns) c << ',' << csvField(k);
    c << ",error,wall_s,cpu_s,runs,steps,iterations_per_step,peak_rss_mb,status,exit_code,run,note\n";
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const auto& r = results[i];
      c << i + 1;
      for (const auto& k : s.columns) {
        std::string v;
        for (const auto& [key, val] : s.points[i].settings)
          if (key == k) v = valueText(val);
        c << ',' << csvField(v);
      }
      c << ',' << num(r.error, 8) << ',' << num(r.wallSeconds, 6) << ',' << num(r.cpuSeconds, 6) << ',' << r.walls.size() << ',' << r.steps << ','
        << num(r.iterationsPerStep, 6) << ',' << num(r.peakRssMb, 6) << ',' << r.status << ',' << r.exitCode << ','
        << csvField(prepared[i].dir.filename().string()) << ',' << csvField(r.note) << '\n';
    }
    writeText(csv, c.str());
  }
  out << "study " << s.name << ": " << ok << " of " << s.points.size() << " points ok; wrote " << csv.string() << "\n";
  const bool cpu = s.cost == Cost::Cpu;
  const std::string why = plotPareto(trade, (root / s.name).string(),
                                     "study " + s.name + ": error against " + (cpu ? "CPU" : "wall") + " time (" +
                                         s.reference + ")",
                                     cpu ? "CPU time per run (user + system, every process) [s]" : "wall time per run [s]");
  if (why.empty())
    out << "study " << s.name << ": wrote " << (root / (s.name + "_pareto.png")).string() << "\n";
  else
    err << "study " << s.name << ": no Pareto plot: " << why << "; the CSV is written\n";
  return ok == s.points.size() ? 0 : 3;
}

}  // namespace mpmice::study
