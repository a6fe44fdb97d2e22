#include "core/io/checkpoint.h"

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <stdexcept>

#include "core/io/h5_file.h"
#include "core/scene/scene.h"

namespace mpmice::core {

namespace {
constexpr std::int64_t kFormat = 1;

std::string where(const CheckpointData& d) { return d.source().empty() ? std::string("checkpoint") : d.source(); }

/// The step of a checkpoint file name `<base>_checkpoint_<step>.h5`, or -1.
long stepOf(const std::string& filename, std::string* base = nullptr) {
  static const std::regex re("^(.*)_checkpoint_([0-9]+)\\.h5$");
  std::smatch m;
  if (!std::regex_match(filename, m, re)) return -1;
  if (base) *base = m[1];
  return std::stol(m[2]);
}
}  // namespace

void CheckpointData::put(const std::string& name, std::vector<double> values) {
  entries_[name] = std::move(values);
}

void CheckpointData::putText(const std::string& name, const std::string& text) {
  std::vector<double> v;
  v.reserve(text.size());
  for (unsigned char c : text) v.push_back(static_cast<double>(c));
  put(name, std::move(v));
}

const std::vector<double>& CheckpointData::get(const std::string& name) const {
  const auto it = entries_.find(name);
  if (it == entries_.end())
    throw std::invalid_argument(where(*this) + ": the checkpoint has no entry '" + name +
                                "' (written by another program or configuration?)");
  return it->second;
}

double CheckpointData::scalar(const std::string& name) const {
  const auto& v = get(name);
  if (v.size() != 1)
    throw std::invalid_argument(where(*this) + ": checkpoint entry '" + name + "' holds " +
                                std::to_string(v.size()) + " values, expected 1");
  return v[0];
}

std::string CheckpointData::text(const std::string& name) const {
  std::string s;
  for (double c : get(name)) s += static_cast<char>(static_cast<unsigned char>(c));
  return s;
}

void CheckpointData::copyTo(const std::string& name, std::span<double> out) const {
  const auto& v = get(name);
  if (v.size() != out.size())
    throw std::invalid_argument(where(*this) + ": checkpoint entry '" + name + "' holds " + std::to_string(v.size()) +
                                " values on this rank, the run has " + std::to_string(out.size()) +
                                " (another scene or decomposition?)");
  std::copy(v.begin(), v.end(), out.begin());
}

std::string checkpointPath(const std::string& dir, const std::string& base, long step) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "_checkpoint_%06ld.h5", step);
  return dir + "/" + base + buf;
}

void writeCheckpoint(const Comm& comm, const std::string& path, const CheckpointData& data, double time, long step) {
  // Every rank must hold the same names: compare the count and a digest of the names.
  std::string names;
  for (const auto& [name, v] : data.entries()) names += name + ";";
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : names) h = (h ^ c) * 1099511628211ull;
  const double digest = static_cast<double>(h >> 12);
  if (comm.max(digest) != comm.min(digest))
    throw std::runtime_error("writeCheckpoint: the ranks hold different entries (" + path + ")");
  const std::string partial = path + ".part";
  std::string err;
  try {
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  } catch (const std::exception&) {
  }
  {
    const H5File file = H5File::create(comm, partial);
    const H5Group root = file.root();
    root.writeAttribute("time", std::vector<double>{time});
    root.writeAttribute("step", std::vector<std::int64_t>{step});
    root.writeAttribute("nranks", std::vector<std::int64_t>{comm.size()});
    root.writeAttribute("format", std::vector<std::int64_t>{kFormat});
    const H5Group dataGroup = root.group("data");
    const H5Group countGroup = root.group("counts");
    const H5PropList dxpl = H5PropList::transferMpio(true);
    const auto nr = static_cast<std::size_t>(comm.size());
    for (const auto& [name, v] : data.entries()) {
      std::vector<double> counts(nr, 0.0);
      counts[static_cast<std::size_t>(comm.rank())] = static_cast<double>(v.size());
      comm.sumInPlace(counts);
      double offset = 0, total = 0;
      for (std::size_t r = 0; r < nr; ++r) {
        if (r < static_cast<std::size_t>(comm.rank())) offset += counts[r];
        total += counts[r];
      }
      const H5Dataset ds = dataGroup.createDataset(name, {static_cast<hsize_t>(total)});
      if (total > 0) {
        H5Dataspace sel = ds.space();
        const auto n = static_cast<hsize_t>(v.size());
        if (n > 0)
          sel.selectBlock({static_cast<hsize_t>(offset)}, {n});
        else
          sel.selectNone();
        const H5Dataspace mem = H5Dataspace::simple({std::max<hsize_t>(n, 1)});
        H5Dataspace memSel = H5Dataspace::simple({std::max<hsize_t>(n, 1)});
        if (n == 0) memSel.selectNone();
        const double dummy = 0;
        ds.write(n > 0 ? v.data() : &dummy, memSel, sel, dxpl.id());
      }
      const H5Dataset cs = countGroup.createDataset(name, {static_cast<hsize_t>(nr)});
      H5Dataspace csel = cs.space();
      if (comm.root())
        csel.selectBlock({0}, {static_cast<hsize_t>(nr)});
      else
        csel.selectNone();
      H5Dataspace cmem = H5Dataspace::simple({static_cast<hsize_t>(nr)});
      if (!comm.root()) cmem.selectNone();
      cs.write(counts.data(), cmem, csel, dxpl.id());
    }
  }
  if (comm.root()) {
    std::error_code ec;
    std::filesystem::rename(partial, path, ec);
    if (ec) err = "writeCheckpoint: cannot rename '" + partial + "' to '" + path + "': " + ec.message();
  }
  err = comm.firstMessage(err);
  if (!err.empty()) throw std::runtime_error(err);
}

CheckpointData readCheckpoint(const Comm& comm, const std::string& path) {
  std::string err;
  if (!std::filesystem::is_regular_file(path)) err = "--restart: no checkpoint file '" + path + "'";
  err = comm.firstMessage(err);
  if (!err.empty()) throw std::invalid_argument(err);
  CheckpointData data;
  data.setSource(path);
  const H5File file = H5File::open(comm, path);
  const H5Group root = file.root();
  if (!root.hasAttribute("format") || root.readAttributeInt("format").at(0) != kFormat || !root.has("data") ||
      !root.has("counts"))
    throw std::invalid_argument(path + ": not a checkpoint of this program version (format " +
                                std::to_string(kFormat) + ")");
  const auto nranks = root.readAttributeInt("nranks").at(0);
  if (nranks != comm.size())
    throw std::invalid_argument(path + ": the checkpoint was written by " + std::to_string(nranks) +
                                " ranks, this run has " + std::to_string(comm.size()) +
                                " (a checkpoint resumes on the rank count that wrote it)");
  const H5Group dataGroup = root.openGroup("data");
  const H5Group countGroup = root.openGroup("counts");
  const H5PropList dxpl = H5PropList::transferMpio(true);
  const auto nr = static_cast<std::size_t>(comm.size());
  for (const std::string& name : dataGroup.members()) {
    std::vector<double> counts(nr, 0.0);
    {
      const H5Dataset cs = countGroup.openDataset(name);
      const H5Dataspace sel = cs.space();
      const H5Dataspace mem = H5Dataspace::simple({static_cast<hsize_t>(nr)});
      cs.read(counts.data(), mem, sel, dxpl.id());
    }
    double offset = 0;
    for (std::size_t r = 0; r < static_cast<std::size_t>(comm.rank()); ++r) offset += counts[r];
    const auto n = static_cast<hsize_t>(counts[static_cast<std::size_t>(comm.rank())]);
    std::vector<double> v(static_cast<std::size_t>(n));
    const H5Dataset ds = dataGroup.openDataset(name);
    const auto total = ds.space().dims().at(0);
    if (total > 0) {
      H5Dataspace sel = ds.space();
      H5Dataspace memSel = H5Dataspace::simple({std::max<hsize_t>(n, 1)});
      if (n > 0) {
        sel.selectBlock({static_cast<hsize_t>(offset)}, {n});
      } else {
        sel.selectNone();
        memSel.selectNone();
      }
      double dummy = 0;
      ds.read(n > 0 ? v.data() : &dummy, memSel, sel, dxpl.id());
    }
    data.put(name, std::move(v));
  }
  return data;
}

std::string resolveCheckpoint(const std::string& path, const std::string& base) {
  namespace fs = std::filesystem;
  if (fs::is_directory(path)) {
    long best = -1;
    for (const auto& e : fs::directory_iterator(path)) {
      std::string b;
      const long s = stepOf(e.path().filename().string(), &b);
      if (s > best && b == base && e.is_regular_file()) best = s;
    }
    if (best < 0)
      throw std::invalid_argument("--restart: the directory '" + path + "' holds no checkpoint " + base +
                                  "_checkpoint_<step>.h5 (output.checkpoint_interval writes them)");
    return checkpointPath(path, base, best);
  }
  const fs::path p(path);
  const long s = stepOf(p.filename().string());
  if (s < 0)
    throw std::invalid_argument("--restart: '" + path +
                                "' is neither an output directory nor a checkpoint file <base>_checkpoint_<step>.h5");
  const std::string dir = p.parent_path().empty() ? std::string(".") : p.parent_path().string();
  const std::string mine = checkpointPath(dir, base, s);
  if (!fs::is_regular_file(mine))
    throw std::invalid_argument("--restart: no checkpoint file '" + mine + "'" +
                                (mine == path ? std::string() : " (the checkpoint of this program at the step of '" + path + "')"));
  return mine;
}

void putSceneIdentity(CheckpointData& data, const Scene& scene, const std::string& program) {
  data.putText("scene.hash", sceneHash(scene));
  data.putText("scene.name", scene.name);
  data.putText("scene.program", program);
}

void checkSceneIdentity(const CheckpointData& data, const Scene& scene, const std::string& program) {
  const std::string hash = data.text("scene.hash"), name = data.text("scene.name");
  if (hash != sceneHash(scene))
    throw std::invalid_argument(data.source() + ": the checkpoint is of another scene (scene '" + name + "', hash " +
                                hash + "; this scene '" + scene.name + "' (" + scene.file + ") has hash " +
                                sceneHash(scene) + ": its mesh, materials or boundary conditions differ)");
  const std::string by = data.text("scene.program");
  if (by != program)
    throw std::invalid_argument(data.source() + ": the checkpoint was written by " + by + ", not by " + program);
}

}  // namespace mpmice::core
