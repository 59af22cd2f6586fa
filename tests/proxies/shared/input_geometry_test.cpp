// requireProxyGeometry: which meshes each generator accepts, the message of each refusal, and
// generateProxy refusing them for every kind and method (these crashed CGAL or OpenMesh, or
// spun, before the check existed).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <thread>

#include "mesh/validation.h"
#include "proxies/general/general_proxy.h"
#include "proxies/inside/inside_proxy.h"
#include "proxies/pipeline/proxy_pipeline.h"
#include "proxies/shared/input_geometry.h"
#include "proxies/shared/time_budget.h"
#include "tests/proxies/shared/gen_test_util.h"
#include "util/error.h"

namespace proxyvis {
namespace {

const std::vector<Triangle> kTetraFaces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

TriMesh tetra(std::vector<Vec3f> vertices) {
  TriMesh m;
  m.source = "tetra.off";
  m.vertices = std::move(vertices);
  m.triangles = kTetraFaces;
  return m;
}

TriMesh regularTetra() {
  return tetra({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
}

TriMesh transformed(const TriMesh& in, float scale, float shift) {
  TriMesh out = in;
  for (Vec3f& v : out.vertices) v = v * scale + Vec3f(shift, shift, shift);
  return out;
}

// The message of the Error requireProxyGeometry throws, or "" when it accepts the mesh.
std::string refusal(const TriMesh& mesh, GeometryNeed need) {
  try {
    requireProxyGeometry(mesh, need, "the test proxy");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(InputGeometry, MeasuresARegularTetrahedron) {
  const GeometryMeasure m = measureGeometry(regularTetra());
  EXPECT_TRUE(m.finite);
  EXPECT_EQ(m.triangles, 4u);
  EXPECT_EQ(m.non_degenerate_triangles, 4u);
  EXPECT_DOUBLE_EQ(m.max_abs, 1.0);
  EXPECT_DOUBLE_EQ(m.diagonal, std::sqrt(3.0));
  // Line through (0,0,0) and (1,0,0): the farthest vertex is at distance 1; the plane through
  // it and the line is z = 0 or y = 0, the last vertex 1 away.
  EXPECT_NEAR(m.width, 1.0, 1e-12);
  EXPECT_NEAR(m.thickness, 1.0, 1e-12);
}

TEST(InputGeometry, AcceptsRealMeshesForEveryNeed) {
  for (const char* name : {"bunny.off", "spot_triangulated.obj"}) {
    const TriMesh& mesh = gen_test::mesh(name);
    EXPECT_EQ(refusal(mesh, GeometryNeed::kSurface), "") << name;
    EXPECT_EQ(refusal(mesh, GeometryNeed::kSolid), "") << name;
  }
}

TEST(InputGeometry, RefusesCollinearVerticesNamingTheFile) {
  const TriMesh collinear = tetra({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}});
  for (GeometryNeed need : {GeometryNeed::kSurface, GeometryNeed::kSolid}) {
    const std::string message = refusal(collinear, need);
    EXPECT_EQ(message.rfind("tetra.off: all vertices lie on one line", 0), 0u) << message;
  }
  // Collinear up to float rounding along a direction no axis has: still one line.
  const TriMesh slanted =
      tetra({{0.1f, 0.2f, 0.3f}, {0.2f, 0.4f, 0.6f}, {0.3f, 0.6f, 0.9f}, {0.4f, 0.8f, 1.2f}});
  EXPECT_NE(refusal(slanted, GeometryNeed::kSurface).find("one line"), std::string::npos);
}

TEST(InputGeometry, RefusesIdenticalPoints) {
  const TriMesh same = tetra({{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}});
  EXPECT_NE(refusal(same, GeometryNeed::kSurface).find("all vertices are at one point"),
            std::string::npos);
}

TEST(InputGeometry, RefusesCoordinatesBeyondTheLimit) {
  const TriMesh huge = tetra({{3e38f, 3e38f, 3e38f},
                              {-3e38f, -3e38f, 3e38f},
                              {-3e38f, 3e38f, -3e38f},
                              {3e38f, -3e38f, -3e38f}});
  EXPECT_NE(refusal(huge, GeometryNeed::kSurface).find("coordinates reach 3e+38"),
            std::string::npos);
  // The limit itself: a tetrahedron scaled to 1e11 passes, to 1e13 not.
  EXPECT_EQ(refusal(transformed(regularTetra(), 1e11f, 0), GeometryNeed::kSolid), "");
  EXPECT_NE(refusal(transformed(regularTetra(), 1e13f, 0), GeometryNeed::kSolid).find("beyond"),
            std::string::npos);
}

TEST(InputGeometry, RefusesAMeshTooFarFromTheOriginForFloat) {
  // The bunny (diagonal 0.26) at 100 keeps ~2.6e-3 of its position: accepted; at 1e4 it spans
  // 2.6e-5 of it (a few hundred float steps): refused, suggesting to translate it.
  const TriMesh& bunny = gen_test::mesh("bunny.off");
  EXPECT_EQ(refusal(transformed(bunny, 1, 100), GeometryNeed::kSurface), "");
  const std::string far = refusal(transformed(bunny, 1, 1e4f), GeometryNeed::kSurface);
  EXPECT_NE(far.find("translate the mesh near the origin"), std::string::npos) << far;
}

TEST(InputGeometry, RefusesATinyMesh) {
  const std::string tiny = refusal(transformed(regularTetra(), 1e-10f, 0), GeometryNeed::kSurface);
  EXPECT_NE(tiny.find("below 1e-09"), std::string::npos) << tiny;
}

TEST(InputGeometry, RefusesNonFiniteCoordinates) {
  TriMesh nan = regularTetra();
  nan.vertices[2].y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(refusal(nan, GeometryNeed::kSurface).find("not finite"), std::string::npos);
  TriMesh inf = regularTetra();
  inf.vertices[1].x = std::numeric_limits<float>::infinity();
  EXPECT_NE(refusal(inf, GeometryNeed::kSurface).find("not finite"), std::string::npos);
}

TEST(InputGeometry, AFlatMeshHasASurfaceButNoVolume) {
  TriMesh quad;
  quad.source = "quad.off";
  quad.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  EXPECT_EQ(refusal(quad, GeometryNeed::kSurface), "");
  EXPECT_NE(refusal(quad, GeometryNeed::kSolid).find("all vertices lie in one plane"),
            std::string::npos);
}

TEST(InputGeometry, EveryTriangleDegenerateIsNoSurface) {
  // The vertices span a plane, but each triangle's corners are collinear.
  TriMesh slivers;
  slivers.source = "slivers.off";
  slivers.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 2, 0}, {0, 3, 0}};
  slivers.triangles = {{0, 1, 2}, {3, 4, 5}};
  const GeometryMeasure m = measureGeometry(slivers);
  EXPECT_EQ(m.non_degenerate_triangles, 0u);
  EXPECT_GT(m.width, 0.5);
  EXPECT_NE(refusal(slivers, GeometryNeed::kSurface).find("all 2 triangles are degenerate"),
            std::string::npos);
}

TEST(InputGeometry, NoTrianglesIsRefused) {
  TriMesh empty;
  empty.source = "empty.off";
  EXPECT_NE(refusal(empty, GeometryNeed::kSurface).find("empty.off: the mesh has no triangles"),
            std::string::npos);
}

// Every kind and method on the inputs that used to crash or spin: an Error, no crash.
TEST(InputGeometry, GenerateProxyRefusesThemForEveryMethod) {
  const std::vector<TriMesh> bad = {
      tetra({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}),
      tetra({{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}}),
      tetra({{3e38f, 3e38f, 3e38f},
             {-3e38f, -3e38f, 3e38f},
             {-3e38f, 3e38f, -3e38f},
             {3e38f, -3e38f, -3e38f}}),
      transformed(gen_test::mesh("bunny.off"), 1e20f, 0),
      transformed(gen_test::mesh("bunny.off"), 1, 1e20f),
  };
  const std::pair<ProxyClass, const char*> methods[] = {
      {ProxyClass::kOutside, "hull"},   {ProxyClass::kOutside, "wrap"},
      {ProxyClass::kInside, "wrap"},    {ProxyClass::kInside, "erode"},
      {ProxyClass::kGeneral, "qem"},    {ProxyClass::kGeneral, "cgal-sms"},
      {ProxyClass::kGeneral, "meshopt"}};
  for (const TriMesh& mesh : bad)
    for (const auto& [kind, method] : methods) {
      ProxyGenOptions o = gen_test::genOptions(kind, method, 0, 100);
      EXPECT_THROW(generateProxy(mesh, o), Error) << method << " on " << mesh.vertices[0].x;
    }
}

TEST(InputGeometry, GenerateProxyChecksOptionRanges) {
  ProxyGenOptions o = gen_test::genOptions(ProxyClass::kOutside, "wrap", 0, 100);
  o.alpha = 0.0005;
  try {
    generateProxy(regularTetra(), o);
    FAIL() << "alpha 0.0005 accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("--alpha must be in [0.001, 1], got 0.0005"),
              std::string::npos)
        << e.what();
  }
  o.alpha.reset();
  o.offset = 10;
  EXPECT_THROW(generateProxy(regularTetra(), o), Error);
}

// Found by fuzz_proxy_gen: a mesh of fewer triangles than the smallest budget (4) made
// meshoptimizer assert (its target above the index count). Every simplifier returns it as is.
TEST(SmallMeshes, SimplifiersKeepAMeshBelowTheSmallestBudget) {
  TriMesh two;
  two.source = "two.off";
  two.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  two.triangles = {{0, 1, 2}, {0, 2, 3}};
  GeneralOptions g;
  g.ratio = 1;
  EXPECT_EQ(simplifyMeshopt(two, g).numTriangles(), 2u);
  EXPECT_EQ(simplifyQem(two, g).numTriangles(), 2u);
  EXPECT_EQ(simplifyCgalSms(two, g).numTriangles(), 2u);
}

// Found by fuzz_proxy_gen: a triangle whose corners weld into one point made CGAL's
// orient_polygon_soup loop for ever (inside kind, --fill-holes). Welding now drops it.
TEST(SmallMeshes, ATriangleDegenerateAfterWeldingIsDropped) {
  TriMesh m = regularTetra();
  m.vertices.push_back(m.vertices[0]);  // vertex 4 = vertex 0
  m.vertices.push_back(m.vertices[0]);  // vertex 5 = vertex 0
  m.triangles.push_back({0, 4, 1});
  m.triangles.push_back({4, 5, 0});
  EXPECT_EQ(validateMesh(m).boundary_edges, 0u);
  size_t holes = 99;
  const TriMesh filled = fillHoles(m, &holes);
  EXPECT_EQ(holes, 0u);
  EXPECT_EQ(filled.numTriangles(), 4u);
}

TEST(TimeBudget, UnlimitedNeverExpiresAndASpentOneThrowsNamingTheSource) {
  const TimeBudget none;
  EXPECT_FALSE(none.limited());
  EXPECT_FALSE(none.expired());
  EXPECT_NO_THROW(none.check("anything"));
  const TimeBudget spent(0.001, "mesh.ply");
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_TRUE(spent.expired());
  try {
    spent.check("the alpha wrap");
    FAIL() << "a spent budget did not throw";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("mesh.ply: stopped: the alpha wrap did not finish", 0),
              0u)
        << e.what();
  }
  EXPECT_FALSE(TimeBudget(60, "m").expired());
}

// A running wrap is stopped by the budget: an Error, no proxy.
TEST(TimeBudget, StopsARunningWrap) {
  ProxyGenOptions o = gen_test::genOptions(ProxyClass::kOutside, "wrap", 0, 100);
  o.alpha = 0.002;
  o.max_seconds = 0.2;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_THROW(generateProxy(gen_test::mesh("dragon.drc"), o), Error);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10);
}

}  // namespace
}  // namespace proxyvis
