#include "core/io/output_reader.h"

#include <algorithm>
#include <stdexcept>

#include "core/io/h5_file.h"

namespace mpmice::core {

namespace {
std::string gridPath(Centering c, const std::string& name) {
  return std::string(c == Centering::Cell ? "grid/cell/" : "grid/node/") + name;
}
}  // namespace

OutputReader::OutputReader(const std::string& path) : file_(std::make_unique<H5File>(H5File::open(path))) {}
OutputReader::OutputReader(const Comm& comm, const std::string& path)
    : file_(std::make_unique<H5File>(H5File::open(comm, path))) {}
OutputReader::~OutputReader() = default;
OutputReader::OutputReader(OutputReader&&) noexcept = default;
OutputReader& OutputReader::operator=(OutputReader&&) noexcept = default;

double OutputReader::time() const { return file_->root().readAttributeDouble("time").at(0); }
int OutputReader::step() const { return static_cast<int>(file_->root().readAttributeInt("step").at(0)); }
int OutputReader::dim() const { return static_cast<int>(file_->root().readAttributeInt("dim").at(0)); }

Mesh OutputReader::mesh() const {
  const H5Group root = file_->root();
  const auto o = root.readAttributeDouble("origin");
  const auto h = root.readAttributeDouble("spacing");
  const auto n = root.readAttributeInt("cells");
  if (o.size() != 3 || h.size() != 3 || n.size() != 3)
    throw std::runtime_error("OutputReader: '" + file_->path() + "' has malformed mesh attributes");
  return Mesh(dim(), {o[0], o[1], o[2]}, {h[0], h[1], h[2]},
              {static_cast<int>(n[0]), static_cast<int>(n[1]), static_cast<int>(n[2])});
}

std::array<bool, 3> OutputReader::periodic() const {
  const H5Group root = file_->root();
  if (!root.hasAttribute("periodic")) return {false, false, false};
  const auto p = root.readAttributeInt("periodic");
  if (p.size() != 3) throw std::runtime_error("OutputReader: '" + file_->path() + "' has a malformed periodic attribute");
  return {p[0] != 0, p[1] != 0, p[2] != 0};
}

int OutputReader::numRanks() const { return static_cast<int>(file_->root().readAttributeInt("nranks").at(0)); }

std::vector<std::string> OutputReader::gridFieldNames(Centering c) const {
  const H5Group root = file_->root();
  const std::string g = c == Centering::Cell ? "grid/cell" : "grid/node";
  if (!root.has(g)) return {};
  auto names = root.openGroup(g).members();
  std::erase(names, "xdmf");  // the XDMF index's companions (node layers of 1D/2D meshes)
  return names;
}

bool OutputReader::hasGridField(Centering c, const std::string& name) const {
  return file_->root().has(gridPath(c, name));
}

std::vector<std::int64_t> OutputReader::shapeOf(const std::string& dataset) const {
  const H5Dataset ds = file_->root().openDataset(dataset);
  std::vector<std::int64_t> shape;
  for (hsize_t d : ds.space().dims()) shape.push_back(static_cast<std::int64_t>(d));
  return shape;
}

OutputReader::Array OutputReader::readBlock(const std::string& dataset, const std::vector<std::int64_t>& start,
                                            const std::vector<std::int64_t>& count) const {
  const H5Dataset ds = file_->root().openDataset(dataset);
  H5Dataspace fileSpace = ds.space();
  const auto dims = fileSpace.dims();
  if (start.size() != dims.size() || count.size() != dims.size())
    throw std::runtime_error("OutputReader: dataset '" + ds.name() + "' in '" + file_->path() + "' has rank " +
                             std::to_string(dims.size()) + ", the read asked for rank " +
                             std::to_string(count.size()));
  std::int64_t n = 1;
  for (std::size_t d = 0; d < dims.size(); ++d) {
    if (start[d] < 0 || count[d] < 0 || static_cast<hsize_t>(start[d] + count[d]) > dims[d])
      throw std::runtime_error("OutputReader: read outside dataset '" + ds.name() + "' in '" + file_->path() +
                               "' (dimension " + std::to_string(d) + ": " + std::to_string(start[d]) + " + " +
                               std::to_string(count[d]) + " > " + std::to_string(dims[d]) + ")");
    n *= count[d];
  }
  Array out;
  out.shape = count;
  out.values.assign(static_cast<std::size_t>(std::max<std::int64_t>(n, 1)), 0.0);
  H5Dataspace mem = H5Dataspace::simple({static_cast<hsize_t>(std::max<std::int64_t>(n, 1))}, ds.file(), ds.name());
  if (n == 0) {
    fileSpace.selectNone();
    mem.selectNone();
  } else {
    fileSpace.selectBlock(std::vector<hsize_t>(start.begin(), start.end()),
                          std::vector<hsize_t>(count.begin(), count.end()));
  }
  if (file_->parallel()) {
    const H5PropList dxpl = H5PropList::transferMpio(true);
    ds.read(out.values.data(), mem, fileSpace, dxpl.id());
  } else {
    ds.read(out.values.data(), mem, fileSpace, H5P_DEFAULT);
  }
  out.values.resize(static_cast<std::size_t>(n));
  return out;
}

OutputReader::Array OutputReader::readGridField(Centering c, const std::string& name) const {
  const std::string path = gridPath(c, name);
  const auto shape = shapeOf(path);
  return readBlock(path, std::vector<std::int64_t>(shape.size(), 0), shape);
}

void OutputReader::readFieldInto(Field& f, const Box& owned) const {
  const std::string path = gridPath(f.centering(), f.name());
  const auto shape = shapeOf(path);
  const int nc = shape.size() == 4 ? static_cast<int>(shape[3]) : 1;
  if (nc != f.ncomp())
    throw std::runtime_error("OutputReader: dataset '/" + path + "' in '" + file_->path() + "' has " +
                             std::to_string(nc) + " components, field '" + f.name() + "' has " +
                             std::to_string(f.ncomp()));
  if (!f.box().contains(owned))
    throw std::runtime_error("OutputReader: field '" + f.name() + "' stores " + f.box().str() +
                             ", which does not hold the requested region " + owned.str());
  std::vector<std::int64_t> start{0, 0, 0}, count{0, 0, 0};
  if (owned.ok()) {
    start = {owned.lo[2], owned.lo[1], owned.lo[0]};
    count = {owned.length(2), owned.length(1), owned.length(0)};
  }
  if (shape.size() == 4) {
    start.push_back(0);
    count.push_back(nc);
  }
  const Array a = readBlock(path, start, count);
  std::size_t q = 0;
  forEach(owned, [&](int i, int j, int k) {
    for (int c = 0; c < nc; ++c) f(i, j, k, c) = a.values[q++];
  });
}

bool OutputReader::hasParticles() const { return file_->root().has("particles"); }

std::vector<std::string> OutputReader::particleArrayNames() const {
  if (!hasParticles()) return {};
  auto names = file_->root().openGroup("particles").members();
  std::erase(names, "xdmf");  // the XDMF index's companions (connectivity, full 3x3 tensors)
  std::stable_partition(names.begin(), names.end(), [](const std::string& n) { return n == "position"; });
  return names;
}

std::vector<std::int64_t> OutputReader::particleCountsPerRank() const {
  if (!hasParticles()) return {};
  return file_->root().openGroup("particles").readAttributeInt("rank_counts");
}

OutputReader::Array OutputReader::readParticleArray(const std::string& name) const {
  const auto shape = shapeOf("particles/" + name);
  return readBlock("particles/" + name, std::vector<std::int64_t>(shape.size(), 0), shape);
}

OutputReader::Array OutputReader::readParticleArray(const std::string& name, std::int64_t first,
                                                    std::int64_t count) const {
  const std::string path = "particles/" + name;
  const auto shape = shapeOf(path);
  std::vector<std::int64_t> start{first}, cnt{count};
  if (shape.size() == 2) {
    start.push_back(0);
    cnt.push_back(shape[1]);
  }
  return readBlock(path, start, cnt);
}

}  // namespace mpmice::core
