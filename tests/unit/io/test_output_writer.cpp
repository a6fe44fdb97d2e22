// OutputWriter + OutputReader: parallel HDF5 round trips of grid fields and particles in 1D, 2D and
// 3D (run with 1 and 4 ranks), and the XDMF index the writer keeps (parsed back and checked
// against the HDF5 files it references).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "core/io/output_reader.h"
#include "core/io/output_writer.h"
#include "test_comm.h"

using namespace mpmice::core;
namespace fs = std::filesystem;

namespace {

/// A distinct value for every (global index, component, step): exact round trips are checked.
double valueAt(int i, int j, int k, int c, int step) {
  return 1.0e6 * c + i + 100.0 * j + 10000.0 * k + 0.25 + 0.5 * step;
}

/// A per-size scratch directory under the build tree, removed when the test ends (kept when the
/// environment sets MPMICE_KEEP_TEST_OUTPUT, to look at the files with h5dump or ParaView).
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name) {
    const Comm& comm = mpmice::test::comm();
    path_ = fs::path(MPMICE_IO_TEST_DIR) / (name + "_np" + std::to_string(comm.size()));
    if (comm.root()) fs::remove_all(path_);
    comm.barrier();
  }
  ~ScratchDir() {
    const Comm& comm = mpmice::test::comm();
    comm.barrier();
    if (comm.root() && !std::getenv("MPMICE_KEEP_TEST_OUTPUT")) fs::remove_all(path_);
  }
  [[nodiscard]] std::string str() const { return path_.string(); }

 private:
  fs::path path_;
};

Mesh testMesh(int dim) { return Mesh(dim, {0.5, -1.0, 2.0}, {0.1, 0.2, 0.3}, {9, 7, 5}); }

/// A field filled on its owned region only (ghosts keep a marker that must never reach the file).
Field makeField(const std::string& name, const Decomposition& d, Centering c, int ncomp, int step) {
  const int rank = mpmice::test::comm().rank();
  Field f(name, c, d.storedBox(rank, c, 1), ncomp, 1, -777.0);
  for (int q = 0; q < ncomp; ++q)
    forEach(d.ownedBox(rank, c), [&](int i, int j, int k) { f(i, j, k, q) = valueAt(i, j, k, q, step); });
  return f;
}

/// Particles: rank r holds 3 + 2r, except rank 1 which holds none.
struct Particles {
  std::vector<double> x, y, z, mass, u, v, w;
  ParticleOutput out;
  Particles(int rank, int dim) {
    const int n = rank == 1 ? 0 : 3 + 2 * rank;
    for (int q = 0; q < n; ++q) {
      x.push_back(1000.0 * rank + q);
      y.push_back(1000.0 * rank + q + 0.5);
      z.push_back(1000.0 * rank + q + 0.75);
      mass.push_back(rank * 100.0 + q + 0.125);
      u.push_back(-1.0 * q - rank);
      v.push_back(-2.0 * q - rank);
      w.push_back(-3.0 * q - rank);
    }
    out.count = n;
    out.position = {x, dim > 1 ? std::span<const double>(y) : std::span<const double>(),
                    dim > 2 ? std::span<const double>(z) : std::span<const double>()};
    out.addScalar("mass", mass);
    std::vector<std::span<const double>> vel{u, v, w};
    vel.resize(static_cast<std::size_t>(std::max(dim, 2)));
    out.addVector("velocity", vel);
  }
};

/// Expected global value of a grid dataset entry, with periodic node images wrapped.
double expected(const Decomposition& d, Centering c, int i, int j, int k, int comp, int step) {
  int idx[3] = {i, j, k};
  if (c == Centering::Node)
    for (int dd = 0; dd < d.mesh().dim(); ++dd)
      if (d.periodic()[dd] && idx[dd] == d.mesh().cells()[dd]) idx[dd] = 0;
  return valueAt(idx[0], idx[1], idx[2], comp, step);
}

void checkGlobal(const OutputReader& r, const Decomposition& d, Centering c, const std::string& name, int ncomp,
                 int step) {
  const auto a = r.readGridField(c, name);
  const Box b = d.domainBox(c);
  std::vector<std::int64_t> shape{b.length(2), b.length(1), b.length(0)};
  if (ncomp > 1) shape.push_back(ncomp);
  ASSERT_EQ(a.shape, shape) << name;
  std::size_t q = 0;
  int bad = 0;
  forEach(b, [&](int i, int j, int k) {
    for (int comp = 0; comp < ncomp; ++comp, ++q)
      if (a.values[q] != expected(d, c, i, j, k, comp, step) && bad++ < 5)
        ADD_FAILURE() << name << " at " << i << "," << j << "," << k << " comp " << comp << ": "
                      << a.values[q] << " != " << expected(d, c, i, j, k, comp, step);
  });
  EXPECT_EQ(bad, 0) << name;
}

}  // namespace

class OutputRoundTrip : public ::testing::TestWithParam<int> {};

TEST_P(OutputRoundTrip, GridFieldsAndParticlesComeBackExactly) {
  const int dim = GetParam();
  const Comm& comm = mpmice::test::comm();
  ScratchDir dir("roundtrip_" + std::to_string(dim) + "d");
  const Mesh m = testMesh(dim);
  for (bool periodic : {false, true}) {
    const Decomposition d(m, comm.size(), {periodic, false, periodic});
    const std::string base = periodic ? "per" : "run";
    OutputWriter w(comm, d, dir.str() + "/out", base);
    Particles p(comm.rank(), dim);
    const std::vector<int> steps{0, 10};
    for (int step : steps) {
      const Field vel = makeField("vel", d, Centering::Cell, 2, step);
      const Field pressure = makeField("pressure", d, Centering::Cell, 1, step);
      const Field mass = makeField("mass", d, Centering::Node, 1, step);
      w.writeStep(step, 1.25e-3 * step, {&vel, &pressure, &mass}, &p.out);
    }

    for (int step : steps) {
      // Serial read of the whole file on every rank.
      const OutputReader r(w.stepPath(step));
      EXPECT_EQ(r.step(), step);
      EXPECT_EQ(r.time(), 1.25e-3 * step);
      EXPECT_EQ(r.dim(), dim);
      EXPECT_EQ(r.mesh(), m);
      EXPECT_EQ(r.periodic(), d.periodic());
      EXPECT_EQ(r.numRanks(), comm.size());
      EXPECT_EQ(r.gridFieldNames(Centering::Cell), (std::vector<std::string>{"pressure", "vel"}));
      EXPECT_EQ(r.gridFieldNames(Centering::Node), (std::vector<std::string>{"mass"}));
      checkGlobal(r, d, Centering::Cell, "vel", 2, step);
      checkGlobal(r, d, Centering::Cell, "pressure", 1, step);
      checkGlobal(r, d, Centering::Node, "mass", 1, step);

      // Particles: concatenated in rank order.
      std::vector<double> x, mass, u, v;
      std::vector<std::int64_t> counts;
      for (int rank = 0; rank < comm.size(); ++rank) {
        Particles pr(rank, dim);
        x.insert(x.end(), pr.x.begin(), pr.x.end());
        mass.insert(mass.end(), pr.mass.begin(), pr.mass.end());
        u.insert(u.end(), pr.u.begin(), pr.u.end());
        v.insert(v.end(), pr.v.begin(), pr.v.end());
        counts.push_back(pr.out.count);
      }
      const auto n = static_cast<std::int64_t>(x.size());
      EXPECT_EQ(r.particleCountsPerRank(), counts);
      EXPECT_EQ(r.particleArrayNames(), (std::vector<std::string>{"position", "mass", "velocity"}));
      const auto pos = r.readParticleArray("position");
      ASSERT_EQ(pos.shape, (std::vector<std::int64_t>{n, 3}));
      const auto pm = r.readParticleArray("mass");
      ASSERT_EQ(pm.shape, (std::vector<std::int64_t>{n}));
      const auto pv = r.readParticleArray("velocity");
      const std::int64_t nv = std::max(dim, 2);
      ASSERT_EQ(pv.shape, (std::vector<std::int64_t>{n, nv}));
      std::int64_t q = 0;
      for (int rank = 0; rank < comm.size(); ++rank) {
        Particles pr(rank, dim);
        for (std::size_t s = 0; s < pr.x.size(); ++s, ++q) {
          const auto qq = static_cast<std::size_t>(q);
          EXPECT_EQ(pos.values[3 * qq + 0], pr.x[s]);
          EXPECT_EQ(pos.values[3 * qq + 1], dim > 1 ? pr.y[s] : 0.0);
          EXPECT_EQ(pos.values[3 * qq + 2], dim > 2 ? pr.z[s] : 0.0);
          EXPECT_EQ(pm.values[qq], pr.mass[s]);
          EXPECT_EQ(pv.values[static_cast<std::size_t>(nv) * qq + 0], pr.u[s]);
          EXPECT_EQ(pv.values[static_cast<std::size_t>(nv) * qq + 1], pr.v[s]);
        }
      }
    }

    // Parallel read (collective): each rank restores its owned region and its own particles.
    const int rank = comm.rank();
    const OutputReader pr(comm, w.stepPath(10));
    EXPECT_EQ(pr.step(), 10);
    for (const Centering c : {Centering::Cell, Centering::Node}) {
      const std::string name = c == Centering::Cell ? "vel" : "mass";
      const int ncomp = c == Centering::Cell ? 2 : 1;
      Field f(name, c, d.storedBox(rank, c, 2), ncomp, 2, -1.0);
      const Box owned = d.ownedBox(rank, c);
      pr.readFieldInto(f, owned);
      for (int comp = 0; comp < ncomp; ++comp)
        forEach(f.box(), [&](int i, int j, int k) {
          const double want = owned.contains(i, j, k) ? valueAt(i, j, k, comp, 10) : -1.0;
          ASSERT_EQ(f(i, j, k, comp), want) << name << " " << i << "," << j << "," << k;
        });
    }
    const auto counts = pr.particleCountsPerRank();
    std::int64_t first = 0;
    for (int r = 0; r < rank; ++r) first += counts[static_cast<std::size_t>(r)];
    const auto mine = pr.readParticleArray("mass", first, counts[static_cast<std::size_t>(rank)]);
    EXPECT_EQ(mine.values, p.mass);
  }
}

INSTANTIATE_TEST_SUITE_P(Dims, OutputRoundTrip, ::testing::Values(1, 2, 3));

namespace {

/// Checks that tags nest properly (a minimal well-formedness check: no attributes with '>').
bool tagsBalanced(const std::string& xml, std::string& why) {
  std::vector<std::string> stack;
  std::size_t pos = 0;
  while ((pos = xml.find('<', pos)) != std::string::npos) {
    const std::size_t end = xml.find('>', pos);
    if (end == std::string::npos) {
      why = "unterminated tag";
      return false;
    }
    const std::string tag = xml.substr(pos + 1, end - pos - 1);
    pos = end + 1;
    if (tag.empty() || tag[0] == '?' || tag[0] == '!') continue;
    if (tag[0] == '/') {
      const std::string name = tag.substr(1);
      if (stack.empty() || stack.back() != name) {
        why = "unexpected </" + name + ">";
        return false;
      }
      stack.pop_back();
    } else if (tag.back() != '/') {
      stack.push_back(tag.substr(0, tag.find_first_of(" \n")));
    }
  }
  if (!stack.empty()) {
    why = "unclosed <" + stack.back() + ">";
    return false;
  }
  return true;
}

}  // namespace

TEST(OutputWriterXdmf, IndexListsEveryStepWithItsTimeAndMatchingDatasets) {
  const Comm& comm = mpmice::test::comm();
  ScratchDir dir("xdmf");
  const Mesh m = testMesh(2);
  const Decomposition d(m, comm.size());
  OutputWriter w(comm, d, dir.str(), "scene");
  Particles p(comm.rank(), 2);
  const std::map<int, double> steps{{0, 0.0}, {5, 2.5e-4}, {10, 5.0e-4}};
  for (const auto& [step, time] : steps) {
    const Field vel = makeField("vel", d, Centering::Cell, 2, step);
    const Field mass = makeField("mass", d, Centering::Node, 1, step);
    w.writeStep(step, time, {&vel, &mass}, &p.out);
  }
  if (!comm.root()) return;

  std::ifstream in(w.xdmfPath());
  ASSERT_TRUE(in) << w.xdmfPath();
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string xml = ss.str();
  std::string why;
  EXPECT_TRUE(tagsBalanced(xml, why)) << why;

  // Two temporal collections (mesh, then particles), each with one grid per step carrying its
  // Time value: the block names every ParaView reader gives stay the same at every time.
  const auto meshAt = xml.find(R"(<Grid Name="mesh" GridType="Collection" CollectionType="Temporal">)");
  const auto partAt = xml.find(R"(<Grid Name="particles" GridType="Collection" CollectionType="Temporal">)");
  ASSERT_NE(meshAt, std::string::npos);
  ASSERT_NE(partAt, std::string::npos);
  EXPECT_LT(meshAt, partAt);
  const std::regex stepRe(R"re(<Grid Name="step_(\d+)" GridType="Uniform">\s*<Time Value="([^"]+)")re");
  std::vector<std::pair<int, double>> found;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), stepRe); it != std::sregex_iterator(); ++it)
    found.emplace_back(std::stoi((*it)[1]), std::stod((*it)[2]));
  ASSERT_EQ(found.size(), 2 * steps.size());  // the mesh's steps, then the particles'
  auto it = steps.begin();
  for (std::size_t i = 0; i < found.size(); ++i) {
    if (i == steps.size()) it = steps.begin();
    EXPECT_EQ(found[i].first, it->first);
    EXPECT_EQ(found[i].second, it->second);
    ++it;
  }
  // A 2D mesh is indexed with two node layers in z (one cell of data), so every reader loads cell data.
  const std::regex topoRe(R"re(<Topology TopologyType="3DCoRectMesh" Dimensions="2 8 10" />)re");
  EXPECT_EQ(std::distance(std::sregex_iterator(xml.begin(), xml.end(), topoRe), std::sregex_iterator()), 3);

  // Every HDF5 DataItem names an existing dataset whose shape is the DataItem's Dimensions.
  const std::regex itemRe(R"re(<DataItem Dimensions="([0-9 ]+)"[^>]*Format="HDF">([^:<]+):/([^<]+)</DataItem>)re");
  int items = 0;
  for (auto m2 = std::sregex_iterator(xml.begin(), xml.end(), itemRe); m2 != std::sregex_iterator(); ++m2) {
    ++items;
    std::vector<std::int64_t> dims;
    std::istringstream ds((*m2)[1]);
    for (std::int64_t v; ds >> v;) dims.push_back(v);
    const std::string file = (fs::path(dir.str()) / std::string((*m2)[2])).string();
    const std::string dataset = (*m2)[3];
    const OutputReader r(file);
    OutputReader::Array a;
    if (dataset.rfind("grid/cell/", 0) == 0) a = r.readGridField(Centering::Cell, dataset.substr(10));
    else if (dataset.rfind("grid/node/", 0) == 0) a = r.readGridField(Centering::Node, dataset.substr(10));
    else a = r.readParticleArray(dataset.substr(10));
    EXPECT_EQ(a.shape, dims) << dataset << " in " << file;
  }
  // Per step: vel, mass (its two-layer companion), particle connectivity, position, mass, velocity.
  EXPECT_EQ(items, 6 * static_cast<int>(steps.size()));
  EXPECT_NE(xml.find(R"(<DataItem Dimensions="2 8 10" NumberType="Float" Precision="8" Format="HDF">)"
                     "scene_000010.h5:/grid/node/xdmf/mass</DataItem>"),
            std::string::npos);
  // Cell data of a 2D mesh keeps one cell in z.
  EXPECT_NE(xml.find(R"(<DataItem Dimensions="1 7 9 2" NumberType="Float" Precision="8" Format="HDF">)"
                     "scene_000010.h5:/grid/cell/vel</DataItem>"),
            std::string::npos);
  EXPECT_NE(xml.find(R"(<Attribute Name="vel" AttributeType="Matrix" Center="Cell">)"), std::string::npos);
  EXPECT_NE(xml.find(R"(<Attribute Name="mass" AttributeType="Scalar" Center="Node">)"), std::string::npos);
  const long long total = [&] {
    long long n = 0;
    for (int r = 0; r < comm.size(); ++r) n += Particles(r, 2).out.count;
    return n;
  }();
  EXPECT_NE(xml.find("<Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" + std::to_string(total) + "\""),
            std::string::npos);
}

TEST(OutputWriterErrors, AFieldMissingItsOwnedRegionFailsOnEveryRank) {
  const Comm& comm = mpmice::test::comm();
  ScratchDir dir("errors");
  const Decomposition d(testMesh(3), comm.size());
  OutputWriter w(comm, d, dir.str(), "bad");
  // Rank 0 passes a field that stores only part of what it owns; every rank must see the error.
  const Box owned = d.ownedBox(comm.rank(), Centering::Cell);
  Box stored = owned;
  if (comm.root()) stored.hi[0] = stored.lo[0];
  const Field f("rho", Centering::Cell, stored, 1, 0, 1.0);
  try {
    w.writeStep(0, 0.0, {&f});
    ADD_FAILURE() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("field 'rho' stores"), std::string::npos) << e.what();
  }
}

TEST(OutputReaderErrors, MissingFilesDatasetsAndOutOfRangeReadsNameWhatFailed) {
  const Comm& comm = mpmice::test::comm();
  ScratchDir dir("reader_errors");
  const Decomposition d(testMesh(2), comm.size());
  OutputWriter w(comm, d, dir.str(), "r");
  const Field rho = makeField("rho", d, Centering::Cell, 1, 0);
  w.writeStep(3, 0.5, {&rho});
  auto message = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "(no error)";
  };
  const std::string missing = dir.str() + "/nope.h5";
  EXPECT_NE(message([&] { OutputReader r(missing); }).find(missing), std::string::npos);
  const OutputReader r(w.stepPath(3));
  EXPECT_FALSE(r.hasParticles());
  EXPECT_TRUE(r.hasGridField(Centering::Cell, "rho"));
  EXPECT_FALSE(r.hasGridField(Centering::Node, "rho"));
  EXPECT_NE(message([&] { (void)r.readGridField(Centering::Node, "rho"); }).find("/grid/node/rho"), std::string::npos);
  EXPECT_NE(message([&] { (void)r.readParticleArray("mass"); }).find("particles/mass"), std::string::npos);
  Field two("rho", Centering::Cell, d.storedBox(comm.rank(), Centering::Cell, 0), 2, 0);
  EXPECT_NE(message([&] { r.readFieldInto(two, d.ownedBox(comm.rank(), Centering::Cell)); }).find("1 components"),
            std::string::npos);
}

TEST(OutputWriterFiles, AKilledWriteNeverLeavesAStepUnderItsFinalName) {
  const Comm& comm = mpmice::test::comm();
  ScratchDir dir("partial");
  const Decomposition d(testMesh(2), comm.size());
  OutputWriter w(comm, d, dir.str(), "part");
  const Field f = makeField("rho", d, Centering::Cell, 1, 0);
  // A complete step: the final name only, no temporary file left.
  const std::string done = w.writeStep(0, 0.0, {&f});
  EXPECT_TRUE(fs::exists(done));
  EXPECT_FALSE(fs::exists(done + ".part"));
  EXPECT_FALSE(fs::exists(w.xdmfPath() + ".tmp"));
  // A write that cannot finish (its temporary name is taken by a folder): nothing appears under
  // the step's name, and the index still lists the complete step only.
  const std::string step1 = (fs::path(dir.str()) / "part_000001.h5").string();
  if (comm.root()) fs::create_directories(step1 + ".part");
  comm.barrier();
  EXPECT_ANY_THROW(w.writeStep(1, 1.0, {&f}));
  EXPECT_FALSE(fs::exists(step1));
  std::ifstream in(w.xdmfPath());
  const std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(xml.find("part_000001.h5"), std::string::npos);
}
