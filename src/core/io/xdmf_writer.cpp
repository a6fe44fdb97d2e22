#include "core/io/xdmf_writer.h"

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
              const std::string& ref) {
  os << indent << "<DataItem Dimensions=\"" << joinDims(dims)
     << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << ref << "</DataItem>\n";
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

std::string XdmfWriter::text() const {
  std::ostringstream os;
  const auto nodes = gridDims(mesh_, Centering::Node, 1);
  const auto& o = mesh_.origin();
  const auto& h = mesh_.spacing();
  os << "<?xml version=\"1.0\" ?>\n"
     << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
     << "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
     << "  <Domain>\n"
     << "    <Grid Name=\"TimeSeries\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const XdmfStep& s : steps_) {
    char stepName[32];
    std::snprintf(stepName, sizeof stepName, "step_%06d", s.step);
    os << "      <Grid Name=\"" << stepName << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
       << "        <Time Value=\"" << num(s.time) << "\" />\n"
       << "        <Grid Name=\"mesh\" GridType=\"Uniform\">\n"
       << "          <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"" << joinDims(nodes) << "\" />\n"
       << "          <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
       << "            <DataItem Name=\"Origin\" Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" "
          "Format=\"XML\">"
       << num(o[2]) << " " << num(o[1]) << " " << num(o[0]) << "</DataItem>\n"
       << "            <DataItem Name=\"Spacing\" Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" "
          "Format=\"XML\">"
       << num(h[2]) << " " << num(h[1]) << " " << num(h[0]) << "</DataItem>\n"
       << "          </Geometry>\n";
    for (const auto& a : s.grid) {
      const bool cell = a.centering == Centering::Cell;
      os << "          <Attribute Name=\"" << a.name << "\" AttributeType=\"" << attributeType(a.ncomp)
         << "\" Center=\"" << (cell ? "Cell" : "Node") << "\">\n";
      dataItem(os, "            ", gridDims(mesh_, a.centering, a.ncomp),
               s.h5file + ":/grid/" + (cell ? "cell/" : "node/") + a.name);
      os << "          </Attribute>\n";
    }
    os << "        </Grid>\n";
    if (s.numParticles >= 0) {
      const std::int64_t n = s.numParticles;
      os << "        <Grid Name=\"particles\" GridType=\"Uniform\">\n"
         << "          <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n
         << "\" NodesPerElement=\"1\" />\n"
         << "          <Geometry GeometryType=\"XYZ\">\n";
      dataItem(os, "            ", {n, 3}, s.h5file + ":/particles/position");
      os << "          </Geometry>\n";
      for (const auto& a : s.particles) {
        os << "          <Attribute Name=\"" << a.name << "\" AttributeType=\"" << attributeType(a.ncomp)
           << "\" Center=\"Node\">\n";
        dataItem(os, "            ", a.ncomp > 1 ? std::vector<std::int64_t>{n, a.ncomp} : std::vector<std::int64_t>{n},
                 s.h5file + ":/particles/" + a.name);
        os << "          </Attribute>\n";
      }
      os << "        </Grid>\n";
    }
    os << "      </Grid>\n";
  }
  os << "    </Grid>\n"
     << "  </Domain>\n"
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

}  // namespace mpmice::core
