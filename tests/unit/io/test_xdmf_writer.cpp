// XdmfWriter: the text it renders for 1D/2D/3D meshes, and how a restart replaces later steps.
#include <gtest/gtest.h>

#include "core/io/xdmf_writer.h"

using namespace mpmice::core;

namespace {
XdmfStep stepRecord(int step, double time) {
  XdmfStep s;
  s.step = step;
  s.time = time;
  s.h5file = "run_" + std::to_string(step) + ".h5";
  s.grid = {{"rho", Centering::Cell, 1}, {"v", Centering::Node, 3}};
  return s;
}
std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}
}  // namespace

TEST(XdmfWriter, GridDimsUseTheThreeDimensionalLayoutWithUnitExtents) {
  const Mesh m1(1, {0, 0, 0}, {0.5, 1, 1}, {8, 1, 1});
  const Mesh m2(2, {0, 0, 0}, {0.5, 0.5, 1}, {8, 4, 1});
  const Mesh m3(3, {0, 0, 0}, {0.5, 0.5, 0.5}, {8, 4, 2});
  using V = std::vector<std::int64_t>;
  EXPECT_EQ(XdmfWriter::gridDims(m1, Centering::Cell, 1), (V{1, 1, 8}));
  EXPECT_EQ(XdmfWriter::gridDims(m1, Centering::Node, 1), (V{1, 1, 9}));
  EXPECT_EQ(XdmfWriter::gridDims(m2, Centering::Cell, 2), (V{1, 4, 8, 2}));
  EXPECT_EQ(XdmfWriter::gridDims(m2, Centering::Node, 1), (V{1, 5, 9}));
  EXPECT_EQ(XdmfWriter::gridDims(m3, Centering::Node, 3), (V{3, 5, 9, 3}));
}

TEST(XdmfWriter, GeometryIsZyxOrderedAndAttributesCarryTheirCentering) {
  const Mesh m(3, {1, 2, 3}, {0.25, 0.5, 0.125}, {8, 4, 2});
  XdmfWriter x(m);
  x.add(stepRecord(7, 0.5));
  const std::string t = x.text();
  EXPECT_NE(t.find(R"(Dimensions="3 5 9")"), std::string::npos) << t;
  EXPECT_NE(t.find(">3 2 1</DataItem>"), std::string::npos) << t;          // origin z y x
  EXPECT_NE(t.find(">0.125 0.5 0.25</DataItem>"), std::string::npos) << t;  // spacing dz dy dx
  EXPECT_NE(t.find(R"(<Attribute Name="rho" AttributeType="Scalar" Center="Cell">)"), std::string::npos);
  EXPECT_NE(t.find(R"(<Attribute Name="v" AttributeType="Vector" Center="Node">)"), std::string::npos);
  EXPECT_NE(t.find(R"(Dimensions="2 4 8" NumberType="Float" Precision="8" Format="HDF">run_7.h5:/grid/cell/rho<)"),
            std::string::npos);
  EXPECT_NE(t.find(R"(Dimensions="3 5 9 3" NumberType="Float" Precision="8" Format="HDF">run_7.h5:/grid/node/v<)"),
            std::string::npos);
  EXPECT_EQ(t.find("particles"), std::string::npos);  // no particles in this step
}

TEST(XdmfWriter, ParticlesBecomeAPolyvertexGrid) {
  const Mesh m(2, {0, 0, 0}, {1, 1, 1}, {4, 4, 1});
  XdmfWriter x(m);
  XdmfStep s = stepRecord(1, 0.1);
  s.numParticles = 12;
  s.particles = {{"mass", 1}, {"velocity", 2}};
  x.add(s);
  const std::string t = x.text();
  EXPECT_NE(t.find(R"(<Topology TopologyType="Polyvertex" NumberOfElements="12")"), std::string::npos);
  EXPECT_NE(t.find(R"(Dimensions="12 3" NumberType="Float" Precision="8" Format="HDF">run_1.h5:/particles/position<)"),
            std::string::npos);
  EXPECT_NE(t.find(R"(Dimensions="12" NumberType="Float" Precision="8" Format="HDF">run_1.h5:/particles/mass<)"),
            std::string::npos);
  EXPECT_NE(t.find(R"(Dimensions="12 2" NumberType="Float" Precision="8" Format="HDF">run_1.h5:/particles/velocity<)"),
            std::string::npos);
}

TEST(XdmfWriter, TimesRoundTripAndARestartReplacesLaterSteps) {
  const Mesh m(1, {0, 0, 0}, {1, 1, 1}, {4, 1, 1});
  XdmfWriter x(m);
  const double t1 = 0.1 + 0.2;  // not exactly representable in few digits
  x.add(stepRecord(0, 0.0));
  x.add(stepRecord(10, t1));
  x.add(stepRecord(20, 2 * t1));
  EXPECT_EQ(count(x.text(), "<Time Value="), 3u);
  x.add(stepRecord(10, t1));  // restarted from step 10: step 20 is gone
  ASSERT_EQ(x.steps().size(), 2u);
  EXPECT_EQ(x.steps().back().step, 10);
  const std::string t = x.text();
  const auto p = t.rfind("<Time Value=\"");
  EXPECT_EQ(std::stod(t.substr(p + 13)), t1);
}
