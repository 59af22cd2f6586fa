// Camera rays: the image centre looks at look_at, the top and bottom edges are fov/2 away, the
// aspect ratio widens the horizontal extent, pixel (0, 0) is at the top left.
#include <gtest/gtest.h>

#include <cmath>

#include "render/camera.h"

namespace proxyvis {
namespace {

TEST(Camera, CentreEdgesAndOrientation) {
  CameraDesc d;
  d.eye = {1, 2, 3};
  d.look_at = {1, 2, -7};
  d.up = {0, 1, 0};
  d.fov_deg = 60;
  d.width = 200;
  d.height = 100;
  const Camera cam(d);
  const Vec3f c = normalize(cam.direction(100, 50));
  EXPECT_NEAR(c.z, -1, 1e-6);
  const double half = 30.0 * 3.14159265358979 / 180.0;
  const Vec3f top = normalize(cam.direction(100, 0));
  EXPECT_NEAR(std::acos(-top.z), half, 1e-5);
  EXPECT_GT(top.y, 0);  // row 0 is the top of the image
  const Vec3f right = cam.direction(200, 50);
  EXPECT_GT(right.x, 0);  // looking down -z with y up, +x is to the right
  EXPECT_NEAR(right.x / -right.z, 2 * std::tan(half), 1e-5);  // aspect 2:1
}

}  // namespace
}  // namespace proxyvis
