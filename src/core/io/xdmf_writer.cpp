#include "core/io/xdmf_writer.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace mpmice::core {

namespace {

/// Shortest of %.15g / %.17g that reads back as exactly v (times and spacings round-trip).
std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.15g", v);
  if (std::strtod(buf, nullptr) != v) std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string joinDims(const std::vector<std::int64_t>& d) {
  std::ostringstream os;
  for (std::size_t i = 0; i < d.size(); ++i) os << (i ? " " : "") << d[i];
  return os.str();
}

/// XDMF attribute type for a component count (ParaView reads Matrix with the last dim as components).
const char* attributeType(int ncomp) {
  switch (ncomp) {
    case 1: return "Scalar";
    case 3: return "Vector";
    case 6: return "Tensor6";
    case 9: return "Tensor";
    default: return "Matrix";
  }
}

void dataItem(std::ostream& os, const std::string& indent, const std::vector<std::int64_t>& dims,
              const std::string& ref, const char* numberType = "Float") {
  os << indent << "<DataItem Dimensions=\"" << joinDims(dims) << "\" NumberType=\"" << numberType
     << "\" Precision=\"8\" Format=\"HDF\">" << ref << "</DataItem>\n";
}

}  // namespace

std::vector<std::int64_t> XdmfWriter::gridDims(const Mesh& mesh, Centering c, int ncomp) {
  const Box b = c == Centering::Cell ? mesh.cellBox() : mesh.nodeBox();
  std::vector<std::int64_t> d{b.length(2), b.length(1), b.length(0)};
  if (ncomp > 1) d.push_back(ncomp);
  return d;
}

void XdmfWriter::add(XdmfStep s) {
  std::erase_if(steps_, [&](const XdmfStep& o) { return o.step >= s.step; });
  steps_.push_back(std::move(s));
}

std::vector<std::int64_t> XdmfWriter::xdmfDims(const Mesh& mesh, Centering c, int ncomp) {
  std::vector<std::int64_t> d = gridDims(mesh, c, ncomp);
  if (c == Centering::Node)
    for (int k = mesh.dim(); k < 3; ++k) d[static_cast<std::size_t>(2 - k)] = 2;
  return d;
}

std::string XdmfWriter::xdmfGridDataset(const Mesh& mesh, Centering c, const std::string& name) {
  const bool layered = c == Centering::Node && mesh.dim() < 3;
  return std::string(c == Centering::Cell ? "grid/cell/" : "grid/node/") + (layered ? "xdmf/" : "") + name;
}

std::string XdmfWriter::text() const {
  std::ostringstream os;
  // Two node layers in every unused direction: the readers then see one cell there (the legacy
  // reader loads no cell data on a mesh one node thick).
  const auto nodes = xdmfDims(mesh_, Centering::Node, 1);
  const auto& o = mesh_.origin();
  const auto& h = mesh_.spacing();
  auto stepName = [](int step) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "step_%06d", step);
    return std::string(buf);
  };
  os << "<?xml version=\"1.0\" ?>\n"
     << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
     << "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
     << "  <Domain>\n"
     << "    <Grid Name=\"mesh\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const XdmfStep& s : steps_) {
    os << "      <Grid Name=\"" << stepName(s.step) << "\" GridType=\"Uniform\">\n"
       << "        <Time Value=\"" << num(s.time) << "\" />\n"
       << "        <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"" << joinDims(nodes) << "\" />\n"
       << "        <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
       << "          <DataItem Name=\"Origin\" Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" "
          "Format=\"XML\">"
       << num(o[2]) << " " << num(o[1]) << " " << num(o[0]) << "</DataItem>\n"
       << "          <DataItem Name=\"Spacing\" Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" "
          "Format=\"XML\">"
       << num(h[2]) << " " << num(h[1]) << " " << num(h[0]) << "</DataItem>\n"
       << "        </Geometry>\n";
    for (const auto& a : s.grid) {
      const bool cell = a.centering == Centering::Cell;
      os << "        <Attribute Name=\"" << a.name << "\" AttributeType=\"" << attributeType(a.ncomp)
         << "\" Center=\"" << (cell ? "Cell" : "Node") << "\">\n";
      dataItem(os, "          ", xdmfDims(mesh_, a.centering, a.ncomp),
               s.h5file + ":/" + xdmfGridDataset(mesh_, a.centering, a.name));
      os << "        </Attribute>\n";
    }
    os << "      </Grid>\n";
  }
  os << "    </Grid>\n";
  const bool anyParticles = std::any_of(steps_.begin(), steps_.end(), [](const XdmfStep& s) { return s.numParticles >= 0; });
  if (anyParticles) {
    os << "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const XdmfStep& s : steps_) {
      if (s.numParticles < 0) continue;
      const std::int64_t n = s.numParticles;
      os << "      <Grid Name=\"" << stepName(s.step) << "\" GridType=\"Uniform\">\n"
         << "        <Time Value=\"" << num(s.time) << "\" />\n"
         << "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n << "\" NodesPerElement=\"1\">\n";
      dataItem(os, "          ", {n}, s.h5file + ":/particles/xdmf/vertex", "Int");
      os << "        </Topology>\n"
         << "        <Geometry GeometryType=\"XYZ\">\n";
      dataItem(os, "          ", {n, 3}, s.h5file + ":/particles/position");
      os << "        </Geometry>\n";
      for (const auto& a : s.particles) {
        // A symmetric tensor (6: xx, yy, zz, xy, yz, xz) is indexed as its full 3x3 companion.
        const bool sym = a.ncomp == 6;
        const int nc = sym ? 9 : a.ncomp;
        os << "        <Attribute Name=\"" << a.name << "\" AttributeType=\"" << attributeType(nc)
           << "\" Center=\"Node\">\n";
        dataItem(os, "          ", nc > 1 ? std::vector<std::int64_t>{n, nc} : std::vector<std::int64_t>{n},
                 s.h5file + ":/particles/" + (sym ? "xdmf/" : "") + a.name);
        os << "        </Attribute>\n";
      }
      os << "      </Grid>\n";
    }
    os << "    </Grid>\n";
  }
  os << "  </Domain>\n"
     << "</Xdmf>\n";
  return os.str();
}

void XdmfWriter::write(const std::string& path) const {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::trunc);
    if (!f) throw std::runtime_error("XDMF: cannot open '" + tmp + "' for writing");
    f << text();
    f.flush();
    if (!f) throw std::runtime_error("XDMF: writing '" + tmp + "' failed");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw std::runtime_error("XDMF: cannot rename '" + tmp + "' to '" + path + "': " + ec.message());
}

// One line per step, fields separated by tabs: step, time (hexadecimal, exact), file, particle
// count, the grid arrays (count, then name, centering 0 cell / 1 node, components each), the
// particle arrays (count, then name, components each).
std::string XdmfWriter::serialize() const {
  std::ostringstream o;
  char t[64];
  for (const XdmfStep& s : steps_) {
    std::snprintf(t, sizeof t, "%a", s.time);
    o << s.step << '\t' << t << '\t' << s.h5file << '\t' << s.numParticles << '\t' << s.grid.size();
    for (const auto& g : s.grid) o << '\t' << g.name << '\t' << (g.centering == Centering::Node ? 1 : 0) << '\t' << g.ncomp;
    o << '\t' << s.particles.size();
    for (const auto& p : s.particles) o << '\t' << p.name << '\t' << p.ncomp;
    o << '\n';
  }
  return o.str();
}

void XdmfWriter::restore(const std::string& text) {
  std::vector<XdmfStep> steps;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::size_t a = 0;
    for (std::size_t b; (b = line.find('\t', a)) != std::string::npos; a = b + 1) f.push_back(line.substr(a, b - a));
    f.push_back(line.substr(a));
    std::size_t k = 0;
    auto next = [&]() -> const std::string& {
      if (k >= f.size()) throw std::invalid_argument("XdmfWriter::restore: a truncated index line '" + line + "'");
      return f[k++];
    };
    XdmfStep s;
    s.step = std::stoi(next());
    s.time = std::strtod(next().c_str(), nullptr);
    s.h5file = next();
    s.numParticles = std::stoll(next());
    for (int n = std::stoi(next()); n > 0; --n) {
      XdmfStep::GridArray g;
      g.name = next();
      g.centering = next() == "1" ? Centering::Node : Centering::Cell;
      g.ncomp = std::stoi(next());
      s.grid.push_back(g);
    }
    for (int n = std::stoi(next()); n > 0; --n) {
      XdmfStep::ParticleArray p;
      p.name = next();
      p.ncomp = std::stoi(next());
      s.particles.push_back(p);
    }
    steps.push_back(std::move(s));
  }
  steps_ = std::move(steps);
}

}  // namespace mpmice::core
