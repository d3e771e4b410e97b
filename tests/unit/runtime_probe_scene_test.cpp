// The probe scene (runtime/src/profile/probe_scene.cpp): where a stylus ball
// first touches each kind of shape.
#include "runtime/src/profile/probe_scene.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mbc::test {

namespace {

using rt::ProbeScene;
using rt::ProbeShape;

ProbeScene sceneOf(ProbeShape shape, double radius = 0.0) {
  ProbeScene scene;
  scene.radius = radius;
  scene.shapes.push_back(shape);
  return scene;
}

ProbeShape cylinder() {
  ProbeShape shape;
  shape.kind = ProbeShape::Kind::Cylinder;
  shape.a = {0, 0, 0};
  shape.radius = 10;
  shape.bottom = -20;
  shape.top = 0;
  return shape;
}

} // namespace

TEST(RuntimeProbeScene, HeadOnContactIsExact) {
  const ProbeScene scene = sceneOf(cylinder(), 2.0);
  const auto f = rt::firstContact(scene, {-40, 0, -5}, {0, 0, -5});
  ASSERT_TRUE(f);
  EXPECT_DOUBLE_EQ(*f * 40.0, 28.0); // the ball touches at x = -12
}

TEST(RuntimeProbeScene, ObliqueContactOnTheCylinder) {
  const ProbeScene scene = sceneOf(cylinder());
  // Along y = 6 the wall is at x = -8.
  const auto f = rt::firstContact(scene, {-40, 6, -5}, {0, 6, -5});
  ASSERT_TRUE(f);
  EXPECT_NEAR(-40.0 + *f * 40.0, -8.0, 1e-6);
}

TEST(RuntimeProbeScene, TopFaceAndMiss) {
  const ProbeScene scene = sceneOf(cylinder(), 1.0);
  const auto down = rt::firstContact(scene, {3, 3, 30}, {3, 3, -30});
  ASSERT_TRUE(down);
  EXPECT_NEAR(30.0 - *down * 60.0, 1.0, 1e-9);
  EXPECT_FALSE(rt::firstContact(scene, {-40, 12, -5}, {40, 12, -5}));
  // Grazing: the ball passes at exactly its radius from the wall.
  const auto graze = rt::firstContact(scene, {-40, 11, -5}, {40, 11, -5});
  ASSERT_TRUE(graze);
  EXPECT_NEAR(-40.0 + *graze * 80.0, 0.0, 1e-3);
}

TEST(RuntimeProbeScene, BoreFromInside) {
  ProbeShape bore = cylinder();
  bore.kind = ProbeShape::Kind::Bore;
  const ProbeScene scene = sceneOf(bore, 1.0);
  const auto f = rt::firstContact(scene, {0, 0, -5}, {0, 40, -5});
  ASSERT_TRUE(f);
  EXPECT_DOUBLE_EQ(*f * 40.0, 9.0);
  // Above the hole the nearest material is the rim: the clearance may be
  // too small, never too large.
  const double clearance = rt::clearance(scene, {0, 0, 5});
  EXPECT_GT(clearance, 0.0);
  EXPECT_LE(clearance, std::hypot(10.0, 5.0) - 1.0);
}

TEST(RuntimeProbeScene, StartingInContact) {
  const ProbeScene scene = sceneOf(cylinder());
  const auto f = rt::firstContact(scene, {0, 0, -5}, {0, 0, 30});
  ASSERT_TRUE(f);
  EXPECT_EQ(*f, 0.0);
}

} // namespace mbc::test
