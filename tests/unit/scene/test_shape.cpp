// Shape membership at hand-picked points, in 2D and 3D, and shapes as read from a scene.
#include <gtest/gtest.h>

#include "core/scene/scene.h"
#include "core/scene/shape.h"

namespace mpmice::core {
namespace {

ShapeSpec box(RealVect lo, RealVect hi) {
  ShapeSpec s;
  s.type = "box";
  s.lo = lo;
  s.hi = hi;
  return s;
}
ShapeSpec sphere(RealVect c, double r) {
  ShapeSpec s;
  s.type = "sphere";
  s.center = c;
  s.radius = r;
  return s;
}
ShapeSpec annulus(RealVect c, double ri, double ro) {
  ShapeSpec s;
  s.type = "annulus";
  s.center = c;
  s.inner_radius = ri;
  s.outer_radius = ro;
  return s;
}
ShapeSpec combine(const std::string& type, std::vector<ShapeSpec> children) {
  ShapeSpec s;
  s.type = type;
  s.children = std::move(children);
  return s;
}

TEST(SceneShape, Box2D) {
  const ShapeSpec b = box({0, 0, 0}, {1, 0.5, 0});
  EXPECT_TRUE(b.contains({0.5, 0.25, 0}, 2));
  EXPECT_TRUE(b.contains({1.0, 0.5, 7}, 2));  // boundary included; z ignored in 2D
  EXPECT_FALSE(b.contains({0.5, 0.6, 0}, 2));
  EXPECT_FALSE(b.contains({-0.01, 0.25, 0}, 2));
}

TEST(SceneShape, Circle2D) {
  const ShapeSpec c = sphere({0.5, 0.5, 0}, 0.2);
  EXPECT_TRUE(c.contains({0.5, 0.5, 0}, 2));
  EXPECT_TRUE(c.contains({0.64, 0.64, 0}, 2));   // r = 0.198
  EXPECT_FALSE(c.contains({0.65, 0.65, 0}, 2));  // r = 0.212
  EXPECT_TRUE(c.contains({0.5, 0.5, 3}, 2));     // z ignored
}

TEST(SceneShape, Annulus2D) {
  const ShapeSpec a = annulus({0, 0, 0}, 0.5, 1.0);
  EXPECT_FALSE(a.contains({0.2, 0.2, 0}, 2));  // hole
  EXPECT_TRUE(a.contains({0.75, 0, 0}, 2));
  EXPECT_TRUE(a.contains({0.5, 0.5, 0}, 2));   // r = 0.707
  EXPECT_FALSE(a.contains({0.8, 0.8, 0}, 2));  // r = 1.13
  EXPECT_TRUE(a.contains({0, 1.0, 0}, 2));     // outer rim included
}

TEST(SceneShape, UnionAndDifference2D) {
  const ShapeSpec u = combine("union", {sphere({0, 0, 0}, 1), box({2, 0, 0}, {3, 1, 0})});
  EXPECT_TRUE(u.contains({0.5, 0.5, 0}, 2));
  EXPECT_TRUE(u.contains({2.5, 0.5, 0}, 2));
  EXPECT_FALSE(u.contains({1.5, 0.5, 0}, 2));
  const ShapeSpec d = combine("difference", {box({0, 0, 0}, {1.2, 1.2, 0}), annulus({0, 0, 0}, 0.5, 1.0),
                                             sphere({1.1, 1.1, 0}, 0.05)});
  EXPECT_TRUE(d.contains({0.2, 0.2, 0}, 2));    // inside the hole: air
  EXPECT_FALSE(d.contains({0.7, 0.1, 0}, 2));   // in the wall
  EXPECT_TRUE(d.contains({1.0, 1.0, 0}, 2));    // outside the wall
  EXPECT_FALSE(d.contains({1.1, 1.1, 0}, 2));   // the second subtracted shape
  EXPECT_FALSE(d.contains({1.3, 0.1, 0}, 2));   // outside the first shape
}

TEST(SceneShape, Shapes3D) {
  const ShapeSpec b = box({0, 0, 0}, {1, 1, 1});
  EXPECT_TRUE(b.contains({0.5, 0.5, 0.5}, 3));
  EXPECT_FALSE(b.contains({0.5, 0.5, 1.5}, 3));
  const ShapeSpec s = sphere({0, 0, 0}, 1);
  EXPECT_TRUE(s.contains({0.5, 0.5, 0.5}, 3));    // r = 0.866
  EXPECT_FALSE(s.contains({0.6, 0.6, 0.6}, 3));   // r = 1.04
  EXPECT_TRUE(s.contains({0.6, 0.6, 0.6}, 2));    // as a circle: r = 0.849
  // A cylinder along y, centred at the origin, length 2: |y| <= 1, x^2 + z^2 <= 0.25.
  ShapeSpec c = sphere({0, 0, 0}, 0.5);
  c.type = "cylinder";
  c.axis = {0, 2, 0};  // need not be unit
  c.length = 2;
  EXPECT_TRUE(c.contains({0.3, 0.9, 0.3}, 3));
  EXPECT_FALSE(c.contains({0.3, 1.1, 0.3}, 3));  // beyond the end
  EXPECT_FALSE(c.contains({0.4, 0.0, 0.4}, 3));  // radial 0.566
  c.length = 0;                                   // infinite
  EXPECT_TRUE(c.contains({0.3, 50, 0.3}, 3));
  // Annulus (tube) along z, length 1.
  ShapeSpec a = annulus({0, 0, 0}, 0.5, 1.0);
  a.length = 1;
  EXPECT_TRUE(a.contains({0.7, 0, 0.4}, 3));
  EXPECT_FALSE(a.contains({0.7, 0, 0.6}, 3));
  EXPECT_FALSE(a.contains({0.3, 0, 0.0}, 3));
  const ShapeSpec d = combine("difference", {b, s});
  EXPECT_TRUE(d.contains({0.9, 0.9, 0.9}, 3));
  EXPECT_FALSE(d.contains({0.1, 0.1, 0.1}, 3));
  const ShapeSpec u = combine("union", {s, box({2, 2, 2}, {3, 3, 3})});
  EXPECT_TRUE(u.contains({2.5, 2.5, 2.5}, 3));
  EXPECT_FALSE(u.contains({1.5, 1.5, 1.5}, 3));
}

TEST(SceneShape, Bounds) {
  const auto b = scene_detail::shapeBounds(annulus({1, 2, 0}, 0.5, 1.0), 2);
  ASSERT_TRUE(b.has_value());
  EXPECT_EQ(b->first, (RealVect{0, 1, 0}));
  EXPECT_EQ(b->second, (RealVect{2, 3, 0}));
  const auto u = scene_detail::shapeBounds(combine("union", {sphere({0, 0, 0}, 1), box({2, 0, 0}, {3, 4, 0})}), 2);
  ASSERT_TRUE(u.has_value());
  EXPECT_EQ(u->first, (RealVect{-1, -1, 0}));
  EXPECT_EQ(u->second, (RealVect{3, 4, 0}));
  ShapeSpec c = sphere({0, 0, 0}, 1);
  c.type = "cylinder";
  EXPECT_FALSE(scene_detail::shapeBounds(c, 3).has_value());  // infinite
  c.length = 4;                                               // along z
  const auto cb = scene_detail::shapeBounds(c, 3);
  ASSERT_TRUE(cb.has_value());
  EXPECT_DOUBLE_EQ(cb->second[2], 2.0);
  EXPECT_DOUBLE_EQ(cb->second[0], 1.0);
}

TEST(SceneShape, ReadFromAScene) {
  const Scene s = parseScene(R"(
mesh: {dim: 2, lower: [0, 0], upper: [2, 2], cells: [4, 4]}
time: {end: 1}
materials: [{name: air, kind: fluid, eos: {type: ideal_gas, gamma: 1.4}}]
geometry:
  - shape:
      type: difference
      shapes:
        - {type: union, shapes: [{type: box, lo: [0, 0], hi: [1, 2]}, {type: circle, center: [1.5, 1], radius: 0.5}]}
        - {type: annulus, center: [0, 0], inner_radius: 0.2, outer_radius: 0.4}
    material: air
    pressure: 1
)",
                             "shapes.yaml");
  const ShapeSpec& sh = s.geometry.at(0).shape;
  EXPECT_TRUE(sh.contains({0.1, 0.1, 0}, 2));    // inside the annulus hole
  EXPECT_FALSE(sh.contains({0.3, 0.0, 0}, 2));   // in the annulus wall
  EXPECT_TRUE(sh.contains({1.8, 1.0, 0}, 2));    // in the circle
  EXPECT_FALSE(sh.contains({1.8, 1.8, 0}, 2));   // outside both
  EXPECT_EQ(sh.children[0].children[1].where.line, 9);  // the text opens with a newline
}

}  // namespace
}  // namespace mpmice::core
