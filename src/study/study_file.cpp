#include "study/study_file.h"

#include <cmath>
#include <filesystem>
#include <set>

#include "study/factors.h"
#include "core/io/time_series.h"
#include "study/key_path.h"
#include "study/reference/references.h"

namespace mpmice::study {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const std::string& file, const std::string& key, const std::string& what) {
  throw StudyError(file + ": " + (key.empty() ? "" : "'" + key + "': ") + what);
}

std::string scalar(const std::string& file, const YAML::Node& n, const std::string& key) {
  if (!n.IsScalar()) fail(file, key, "expected a string");
  return n.Scalar();
}

/// The key-value pairs of a mapping, in the file's order.
std::vector<std::pair<std::string, YAML::Node>> pairs(const std::string& file, const YAML::Node& n,
                                                     const std::string& key) {
  if (!n.IsMap()) fail(file, key, "expected a mapping of scene key paths to values");
  std::vector<std::pair<std::string, YAML::Node>> out;
  for (const auto& kv : n) {
    const std::string k = kv.first.as<std::string>();
    try {
      if (k != "ranks") parseKeyPath(k);
    } catch (const KeyPathError& e) {
      fail(file, key, e.what());
    }
    out.emplace_back(k, kv.second);
  }
  return out;
}

void checkRanks(const std::string& file, const YAML::Node& v, const std::string& key) {
  int r = 0;
  try {
    r = v.as<int>();
  } catch (const YAML::Exception&) {
    fail(file, key, "ranks must be an integer >= 1, got '" + valueText(v) + "'");
  }
  if (r < 1) fail(file, key, "ranks must be an integer >= 1, got " + std::to_string(r));
}

/// A factor's levels: a mapping is the settings one level changes; anything else is one value of
/// the key path the factor is named after.
std::vector<Settings> levelsOf(const std::string& file, const std::string& where, const std::string& name,
                               const YAML::Node& n) {
  if (!n.IsSequence() || n.size() == 0)
    fail(file, where, "expected a non-empty list of levels (values of '" + name + "', or mappings of key paths to values)");
  std::vector<Settings> levels;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const std::string at = where + "[" + std::to_string(i) + "]";
    if (n[i].IsMap()) {
      levels.push_back(pairs(file, n[i], at));
      continue;
    }
    try {
      parseKeyPath(name);
    } catch (const KeyPathError&) {
      fail(file, at, "a level of a factor named '" + name + "' (not a key path) must be a mapping of key paths to values");
    }
    levels.push_back(Settings{{name, n[i]}});
  }
  return levels;
}

/// `base`, `factors` and `slices` (the one-factor-at-a-time form) into the points.
std::vector<Point> factorPoints(const std::string& file, const YAML::Node& root) {
  if (!root["base"]) fail(file, "base", "required with `factors`: the centre point, every varied key with its value");
  const Settings base = pairs(file, root["base"], "base");
  std::vector<Factor> factors;
  if (!root["factors"].IsMap() || root["factors"].size() == 0)
    fail(file, "factors", "expected a mapping of factor names (or key paths) to their levels");
  for (const auto& kv : root["factors"]) {
    const std::string name = kv.first.as<std::string>();
    factors.push_back(Factor{name, levelsOf(file, "factors." + name, name, kv.second)});
  }
  std::vector<Slice> slices;
  if (root["slices"]) {
    if (!root["slices"].IsSequence()) fail(file, "slices", "expected a list of mappings (factor: all, or its levels)");
    for (std::size_t i = 0; i < root["slices"].size(); ++i) {
      const YAML::Node sl = root["slices"][i];
      const std::string at = "slices[" + std::to_string(i) + "]";
      if (!sl.IsMap() || sl.size() < 2) fail(file, at, "expected a mapping of two or more factors (factor: all, or its levels)");
      Slice slice;
      for (const auto& kv : sl) {
        const std::string name = kv.first.as<std::string>();
        if (kv.second.IsScalar() && kv.second.Scalar() == "all") {
          const Factor* f = nullptr;
          for (const auto& g : factors) f = g.name == name ? &g : f;
          if (!f) fail(file, at + "." + name, "`all` needs a factor of that name in `factors`");
          slice.factors.push_back(*f);
        } else {
          slice.factors.push_back(Factor{name, levelsOf(file, at + "." + name, name, kv.second)});
        }
      }
      slices.push_back(slice);
    }
  }
  try {
    return expandFactors(base, factors, slices);
  } catch (const std::invalid_argument& e) {
    fail(file, "factors", e.what());
  }
}

}  // namespace

Study readStudy(const std::string& path) {
  Study s;
  s.file = path;
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    fail(path, "", "cannot read the study file");
  } catch (const YAML::Exception& e) {
    fail(path, "", std::string("not valid YAML: ") + e.what());
  }
  const std::string keys =
      "study, scene, program, reference, reference_curve, reference_column, time_limit, repeats, cost, set, axes, "
      "points, base, factors, slices";
  if (!root.IsMap()) fail(path, "", "expected a mapping (" + keys + ")");
  const std::set<std::string> known{"study",      "scene",   "program", "reference", "reference_curve",
                                    "reference_column", "time_limit", "repeats", "cost", "set",
                                    "axes",       "points",  "base",    "factors",   "slices"};
  for (const auto& kv : root) {
    const std::string k = kv.first.as<std::string>();
    if (!known.count(k)) fail(path, k, "unknown key (valid: " + keys + ")");
  }
  s.name = root["study"] ? scalar(path, root["study"], "study") : fs::path(path).stem().string();
  if (s.name.empty() || s.name.find('/') != std::string::npos) fail(path, "study", "expected a name without '/'");
  if (!root["scene"]) fail(path, "scene", "required: the base scene file (relative to the study file)");
  const fs::path scene = scalar(path, root["scene"], "scene");
  s.scene = (scene.is_absolute() ? scene : fs::path(path).parent_path() / scene).lexically_normal().string();
  if (!fs::is_regular_file(s.scene)) fail(path, "scene", "no scene file " + s.scene);
  const std::string program = root["program"] ? scalar(path, root["program"], "program") : "mpmice";
  if (program == "mpmice") s.program = Program::Mpmice;
  else if (program == "coupler_run") s.program = Program::CouplerRun;
  else fail(path, "program", "'" + program + "' is not a program (valid: mpmice, coupler_run)");
  if (!root["reference"]) fail(path, "reference", "required (valid: " + referenceNames() + ")");
  s.reference = scalar(path, root["reference"], "reference");
  const Reference* ref = nullptr;
  try {
    ref = &findReference(s.reference);
  } catch (const std::invalid_argument& e) {
    fail(path, "reference", e.what());
  }
  if (ref->readsCurve) {
    if (!root["reference_curve"])
      fail(path, "reference_curve",
           "required with the reference " + s.reference + ": a CSV with `time` and the probe column (relative to the study file)");
    if (!root["reference_column"])
      fail(path, "reference_column", "required with the reference " + s.reference + ": the probe column compared (e.g. tip_ux)");
    const fs::path curve = scalar(path, root["reference_curve"], "reference_curve");
    s.referenceCurve = (curve.is_absolute() ? curve : fs::path(path).parent_path() / curve).lexically_normal().string();
    s.referenceColumn = scalar(path, root["reference_column"], "reference_column");
    core::TimeSeries c;
    try {
      c = core::readTimeSeriesFile(s.referenceCurve, s.referenceColumn);
    } catch (const std::invalid_argument& e) {
      fail(path, "reference_curve", e.what());
    }
    if (c.t.size() < 2) fail(path, "reference_curve", s.referenceCurve + ": expected at least 2 rows of data");
  } else {
    for (const char* k : {"reference_curve", "reference_column"})
      if (root[k]) fail(path, k, "only a reference that reads a curve takes it (probe_curve); this study's is " + s.reference);
  }
  if (root["time_limit"]) {
    try {
      s.timeLimit = root["time_limit"].as<double>();
    } catch (const YAML::Exception&) {
      fail(path, "time_limit", "expected a number of seconds > 0");
    }
    if (!(s.timeLimit > 0) || !std::isfinite(s.timeLimit)) fail(path, "time_limit", "expected a number of seconds > 0");
  }
  if (root["repeats"]) {
    try {
      s.repeats = root["repeats"].as<int>();
    } catch (const YAML::Exception&) {
      fail(path, "repeats", "expected an integer >= 1");
    }
    if (s.repeats < 1) fail(path, "repeats", "expected an integer >= 1, got " + std::to_string(s.repeats));
  }
  if (root["cost"]) {
    const std::string cost = scalar(path, root["cost"], "cost");
    if (cost == "wall") s.cost = Cost::Wall;
    else if (cost == "cpu") s.cost = Cost::Cpu;
    else fail(path, "cost", "'" + cost + "' is not a cost (valid: wall, cpu)");
  }
  if (root["set"]) s.set = pairs(path, root["set"], "set");
  for (const auto& [k, v] : s.set)
    if (k == "ranks") fail(path, "set", "'ranks' is an axis or a point setting, not a `set` entry");
  const int forms = (root["axes"] ? 1 : 0) + (root["points"] ? 1 : 0) + (root["factors"] ? 1 : 0);
  if (forms > 1)
    fail(path, root["points"] ? "points" : "factors",
         "give one form only: `axes` (the full grid), `points` (a list) or `factors` (one at a time), not both");
  if ((root["base"] || root["slices"]) && !root["factors"])
    fail(path, root["base"] ? "base" : "slices", "belongs to the one-factor-at-a-time form: `factors` is missing");
  if (root["factors"]) {
    s.points = factorPoints(path, root);
  } else if (root["axes"]) {
    for (const auto& [k, v] : pairs(path, root["axes"], "axes")) {
      if (!v.IsSequence() || v.size() == 0) fail(path, "axes." + k, "expected a non-empty list of values");
      Axis a{k, {}};
      for (const auto& x : v) a.values.push_back(x);
      s.axes.push_back(a);
    }
    s.points = expandGrid(s.axes);
  } else if (root["points"]) {
    if (!root["points"].IsSequence() || root["points"].size() == 0)
      fail(path, "points", "expected a non-empty list of mappings (key path: value)");
    for (std::size_t i = 0; i < root["points"].size(); ++i)
      s.points.push_back(Point{pairs(path, root["points"][i], "points[" + std::to_string(i) + "]")});
  } else {
    fail(path, "axes", "required: `axes` (the full grid), `points` (an explicit list) or `factors` (one at a time)");
  }
  for (const auto& p : s.points)
    for (const auto& [k, v] : p.settings) {
      if (k == "ranks") {
        checkRanks(path, v, k);
        if (s.program != Program::Mpmice)
          fail(path, k, "the ranks of `coupler_run` are the scene's keys coupling.ranks.mpm and coupling.ranks.ice");
      }
      bool seen = false;
      for (const auto& c : s.columns) seen = seen || c == k;
      if (!seen) s.columns.push_back(k);
    }
  return s;
}

YAML::Node variantScene(const Study& s, const YAML::Node& base, const Point& p, const std::string& runDir) {
  YAML::Node scene = YAML::Clone(base);
  auto apply = [&](const std::string& where, const std::string& key, const YAML::Node& v) {
    if (key == "ranks") return;
    try {
      setKeyPath(scene, key, v);
    } catch (const KeyPathError& e) {
      fail(s.file, where, std::string(e.what()) + " (in the scene " + s.scene + ")");
    }
  };
  for (const auto& [k, v] : s.set) apply("set", k, v);
  for (const auto& [k, v] : p.settings) apply(s.axes.empty() ? "points" : "axes", k, v);
  scene["output"]["directory"] = runDir;
  return scene;
}

int pointRanks(const Point& p) {
  for (const auto& [k, v] : p.settings)
    if (k == "ranks") return v.as<int>();
  return 1;
}

}  // namespace mpmice::study
