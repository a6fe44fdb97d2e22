#include "core/io/output_writer.h"

#include <array>
#include <cstdio>
#include <filesystem>
#include <set>
#include <stdexcept>

#include "core/io/h5_file.h"
#include "core/io/run_metadata.h"

namespace mpmice::core {

namespace {

/// Throws the same error on every rank when any rank found a problem (avoids a collective hang).
void agree(const Comm& comm, const std::string& localError) {
  const int bad = comm.max(localError.empty() ? 0 : 1);
  if (!bad) return;
  // Share the first failing rank's message so every rank reports the same error.
  const int mine = localError.empty() ? comm.size() : comm.rank();
  int first = mine;
  MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm.raw());
  int len = comm.rank() == first ? static_cast<int>(localError.size()) : 0;
  MPI_Bcast(&len, 1, MPI_INT, first, comm.raw());
  std::string msg = comm.rank() == first ? localError : std::string(static_cast<std::size_t>(len), ' ');
  MPI_Bcast(msg.data(), len, MPI_CHAR, first, comm.raw());
  throw std::runtime_error(msg + (comm.size() > 1 ? " (rank " + std::to_string(first) + ")" : ""));
}

bool validName(const std::string& n) { return !n.empty() && n.find('/') == std::string::npos && n != "."; }

/// Writes a dense C-order block (z,y,x[,comp]) of `buf` into `ds` at `start` (collective).
void writeBlock(const H5Dataset& ds, const std::vector<hsize_t>& start, const std::vector<hsize_t>& count,
                const std::vector<double>& buf, hid_t dxpl) {
  H5Dataspace fileSpace = ds.space();
  hsize_t n = 1;
  for (hsize_t c : count) n *= c;
  H5Dataspace mem = H5Dataspace::simple({n > 0 ? n : 1}, ds.file(), ds.name());
  if (n == 0) {
    fileSpace.selectNone();
    mem.selectNone();
  } else {
    fileSpace.selectBlock(start, count);
  }
  const double dummy = 0.0;  // HDF5 wants a buffer even for an empty selection
  ds.write(n > 0 ? buf.data() : &dummy, mem, fileSpace, dxpl);
}

}  // namespace

OutputWriter::OutputWriter(const Comm& comm, const Decomposition& decomp, std::string directory,
                           std::string baseName)
    : comm_(comm), decomp_(decomp), dir_(std::move(directory)), base_(std::move(baseName)), xdmf_(decomp.mesh()) {
  if (decomp_.numRanks() != comm_.size())
    throw std::invalid_argument("OutputWriter: decomposition has " + std::to_string(decomp_.numRanks()) +
                                " ranks but the communicator has " + std::to_string(comm_.size()));
  std::string err;
  if (comm_.root()) {
    std::error_code ec;
    std::filesystem::create_directories(dir_, ec);
    if (ec) err = "OutputWriter: cannot create output directory '" + dir_ + "': " + ec.message();
  }
  agree(comm_, err);
  comm_.barrier();
}

std::string OutputWriter::stepPath(int step) const {
  char buf[32];
  std::snprintf(buf, sizeof buf, "_%06d.h5", step);
  return (std::filesystem::path(dir_) / (base_ + buf)).string();
}

std::string OutputWriter::xdmfPath() const { return (std::filesystem::path(dir_) / (base_ + ".xmf")).string(); }

std::string OutputWriter::writeStep(int step, double time, const std::vector<const Field*>& gridFields,
                                    const ParticleOutput* particles) {
  const int rank = comm_.rank();
  const Mesh& mesh = decomp_.mesh();

  // 1. Check the inputs on every rank before any collective HDF5 call.
  std::string err;
  std::set<std::pair<int, std::string>> seen;
  for (const Field* f : gridFields) {
    if (!f) {
      err = "OutputWriter: null field pointer in step " + std::to_string(step);
      break;
    }
    const Box owned = decomp_.ownedBox(rank, f->centering());
    if (!validName(f->name()))
      err = "OutputWriter: field name '" + f->name() + "' is not a valid dataset name (empty or contains '/')";
    else if (!seen.insert({static_cast<int>(f->centering()), f->name()}).second)
      err = "OutputWriter: field '" + f->name() + "' given twice in step " + std::to_string(step);
    else if (!f->box().contains(owned))
      err = "OutputWriter: field '" + f->name() + "' stores " + f->box().str() + " but this rank owns " +
            owned.str();
    if (!err.empty()) break;
  }
  if (err.empty() && particles) {
    const auto n = static_cast<std::size_t>(particles->count);
    auto check = [&](std::span<const double> s, const std::string& what, bool mayBeEmpty) {
      if (err.empty() && s.size() != n && !(mayBeEmpty && s.empty()))
        err = "OutputWriter: particle array '" + what + "' has " + std::to_string(s.size()) +
              " values for " + std::to_string(n) + " particles";
    };
    if (particles->count < 0) err = "OutputWriter: negative particle count";
    for (int d = 0; d < 3; ++d) check(particles->position[d], "position[" + std::to_string(d) + "]", true);
    for (const auto& s : particles->scalars) {
      check(s.values, s.name, false);
      if (!validName(s.name) || s.name == "position") err = "OutputWriter: bad particle array name '" + s.name + "'";
    }
    for (const auto& v : particles->vectors) {
      if (v.components.empty()) err = "OutputWriter: particle vector '" + v.name + "' has no components";
      for (const auto& c : v.components) check(c, v.name, false);
      if (!validName(v.name) || v.name == "position") err = "OutputWriter: bad particle array name '" + v.name + "'";
    }
  }
  agree(comm_, err);
  const int anyParticles = comm_.max(particles ? 1 : 0);
  agree(comm_, anyParticles && !particles
                   ? "OutputWriter: some ranks passed particles and this one did not; pass an empty ParticleOutput"
                   : "");

  // 2. The file, its attributes, the grid fields and the particles.
  const std::string path = stepPath(step);
  XdmfStep rec;
  rec.step = step;
  rec.time = time;
  rec.h5file = std::filesystem::path(path).filename().string();
  // Written under a temporary name, renamed when complete: a run killed mid-write leaves no
  // partial file under the step's name.
  const std::string partial = path + ".part";
  {
    const H5File file = H5File::create(comm_, partial);
    const H5Group root = file.root();
    root.writeAttribute("time", std::vector<double>{time});
    root.writeAttribute("step", std::vector<std::int64_t>{step});
    root.writeAttribute("dim", std::vector<std::int64_t>{mesh.dim()});
    root.writeAttribute("origin", std::vector<double>(mesh.origin().begin(), mesh.origin().end()));
    root.writeAttribute("spacing", std::vector<double>(mesh.spacing().begin(), mesh.spacing().end()));
    root.writeAttribute("cells", std::vector<std::int64_t>(mesh.cells().begin(), mesh.cells().end()));
    root.writeAttribute("nranks", std::vector<std::int64_t>{comm_.size()});
    const auto& per = decomp_.periodic();
    root.writeAttribute("periodic", std::vector<std::int64_t>{per[0], per[1], per[2]});
    // What the run is (program, version, command line, ranks, start, scene): its RunRecord's.
    if (const RunMetadata* run = RunMetadata::current()) run->writeTo(root);
    const H5Group cells = root.group("grid/cell");
    const H5Group nodes = root.group("grid/node");
    for (const Field* f : gridFields) {
      writeGridField(f->centering() == Centering::Cell ? cells : nodes, *f);
      rec.grid.push_back({f->name(), f->centering(), f->ncomp()});
    }
    if (particles) {
      writeParticles(root, *particles);
      rec.numParticles = comm_.sum(static_cast<long long>(particles->count));
      for (const auto& s : particles->scalars) rec.particles.push_back({s.name, 1});
      for (const auto& v : particles->vectors)
        rec.particles.push_back({v.name, static_cast<int>(v.components.size())});
    }
  }

  err.clear();
  if (comm_.root()) {
    std::error_code ec;
    std::filesystem::rename(partial, path, ec);
    if (ec) err = "OutputWriter: cannot rename '" + partial + "' to '" + path + "': " + ec.message();
  }
  agree(comm_, err);

  // 3. The XDMF index over every step so far (rank 0 writes; all ranks keep the record).
  xdmf_.add(std::move(rec));
  writeIndex();
  return path;
}

void OutputWriter::writeIndex() const {
  std::string err;
  if (comm_.root()) {
    try {
      xdmf_.write(xdmfPath());
    } catch (const std::exception& e) {
      err = e.what();
    }
  }
  agree(comm_, err);
}

void OutputWriter::resumeIndex(const std::string& serialized) {
  xdmf_.restore(serialized);
  writeIndex();
}

void OutputWriter::writeGridField(const H5Group& group, const Field& f) const {
  const Mesh& mesh = decomp_.mesh();
  const int nc = f.ncomp();
  std::vector<hsize_t> dims;
  for (std::int64_t d : XdmfWriter::gridDims(mesh, f.centering(), nc)) dims.push_back(static_cast<hsize_t>(d));
  const H5PropList dxpl = H5PropList::transferMpio(true);
  const Box owned = decomp_.ownedBox(comm_.rank(), f.centering());
  const auto& per = decomp_.periodic();

  // Writes the field into `ds`: the owned region, then (nodes) the periodic images, each shifted
  // by `layer` (z,y,x) in the dataset. Every rank makes the same sequence of (collective) writes.
  auto writeAll = [&](const H5Dataset& ds, const std::array<hsize_t, 3>& layer) {
    // Writes region `src` of the field at global position `dst` (same shape).
    auto writeRegion = [&](const Box& src, const Box& dst) {
      std::vector<double> buf;
      buf.reserve(static_cast<std::size_t>(src.numPts() * nc));
      forEach(src, [&](int i, int j, int k) {
        for (int c = 0; c < nc; ++c) buf.push_back(f(i, j, k, c));
      });
      std::vector<hsize_t> start, count;
      if (src.ok()) {
        start = {hsize_t(dst.lo[2]) + layer[0], hsize_t(dst.lo[1]) + layer[1], hsize_t(dst.lo[0]) + layer[2]};
        count = {hsize_t(src.length(2)), hsize_t(src.length(1)), hsize_t(src.length(0))};
      } else {
        start = {0, 0, 0};
        count = {0, 0, 0};
      }
      if (nc > 1) {
        start.push_back(0);
        count.push_back(hsize_t(nc));
      }
      writeBlock(ds, start, count, buf, dxpl.id());
    };
    writeRegion(owned, owned);
    // Periodic node images: node n of a periodic direction is node 0, owned by the low rank.
    if (f.centering() != Centering::Node) return;
    for (int mask = 1; mask < 8; ++mask) {
      bool used = true;
      for (int d = 0; d < 3; ++d)
        if ((mask >> d & 1) && !(d < mesh.dim() && per[d])) used = false;
      if (!used) continue;
      Box src = owned;
      IntVect shift{0, 0, 0};
      for (int d = 0; d < 3; ++d)
        if (mask >> d & 1) {
          src.hi[d] = std::min(src.hi[d], 0);
          src.lo[d] = std::max(src.lo[d], 0);
          shift[d] = mesh.cells()[d];
        }
      writeRegion(src, src.ok() ? src.shift(shift) : src);
    }
  };
  writeAll(group.createDataset(f.name(), dims), {0, 0, 0});

  // Node data of a 1D/2D mesh: the XDMF index shows two node layers in unused directions (so
  // that every reader loads the cell data), read from a companion holding the layer in each.
  if (f.centering() != Centering::Node || mesh.dim() == 3) return;
  std::vector<hsize_t> ldims;
  for (std::int64_t d : XdmfWriter::xdmfDims(mesh, f.centering(), nc)) ldims.push_back(static_cast<hsize_t>(d));
  const H5Dataset layered = group.group("xdmf").createDataset(f.name(), ldims);
  const hsize_t ny = mesh.dim() < 2 ? 2 : 1;
  for (hsize_t z = 0; z < 2; ++z)
    for (hsize_t y = 0; y < ny; ++y) writeAll(layered, {z, y, 0});
}

void OutputWriter::writeParticles(const H5Group& root, const ParticleOutput& p) const {
  long long local = p.count, offset = 0;
  MPI_Exscan(&local, &offset, 1, MPI_LONG_LONG, MPI_SUM, comm_.raw());
  if (comm_.rank() == 0) offset = 0;  // MPI_Exscan leaves rank 0's result undefined
  std::vector<long long> counts(static_cast<std::size_t>(comm_.size()));
  MPI_Allgather(&local, 1, MPI_LONG_LONG, counts.data(), 1, MPI_LONG_LONG, comm_.raw());
  long long total = 0;
  for (long long c : counts) total += c;

  const H5Group g = root.group("particles");
  (void)g.group("xdmf");  // what only the XDMF index reads: connectivity, full tensors
  g.writeAttribute("rank_counts", std::vector<std::int64_t>(counts.begin(), counts.end()));
  const H5PropList dxpl = H5PropList::transferMpio(true);
  const auto n = static_cast<std::size_t>(local);

  // One (n, ncomp) dataset from per-component spans (an empty span writes zeros).
  auto writeArray = [&](const std::string& name, const std::vector<std::span<const double>>& comps, bool vector) {
    const hsize_t nc = comps.size();
    std::vector<hsize_t> dims{hsize_t(total)}, start{hsize_t(offset)}, count{hsize_t(local)};
    if (vector) {
      dims.push_back(nc);
      start.push_back(0);
      count.push_back(nc);
    }
    const H5Dataset ds = g.createDataset(name, dims);
    std::vector<double> buf(n * nc, 0.0);
    for (std::size_t c = 0; c < nc; ++c)
      if (!comps[c].empty())
        for (std::size_t q = 0; q < n; ++q) buf[q * nc + c] = comps[c][q];
    // No particle on any rank (a scene whose solids are all cut away): the empty dataset has no
    // storage to write into (HDF5 "addr overflow"), so it stays as created, with zero rows.
    if (total > 0) writeBlock(ds, start, count, buf, dxpl.id());
  };

  writeArray("position", {p.position[0], p.position[1], p.position[2]}, true);
  for (const auto& s : p.scalars) writeArray(s.name, {s.values}, false);
  for (const auto& v : p.vectors) {
    writeArray(v.name, v.components, v.components.size() > 1);
    // A symmetric tensor (xx, yy, zz, xy, yz, xz) also as its full 3x3, row by row (xx xy xz yx
    // yy yz zx zy zz): the component order every ParaView reader agrees on.
    if (v.components.size() == 6) {
      const auto& c = v.components;
      writeArray("xdmf/" + v.name, {c[0], c[3], c[5], c[3], c[1], c[4], c[5], c[4], c[2]}, true);
    }
  }
  // The Polyvertex connectivity: particle q is vertex q (global numbering, stored as doubles).
  std::vector<double> vertex(n);
  for (std::size_t q = 0; q < n; ++q) vertex[q] = static_cast<double>(offset) + static_cast<double>(q);
  writeArray("xdmf/vertex", {std::span<const double>(vertex)}, false);
}

}  // namespace mpmice::core
