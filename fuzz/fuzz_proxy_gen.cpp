// libFuzzer target: every proxy generator (kind x method) on tiny meshes whose coordinates come
// from the fuzz bytes, extreme values included (0, -0, denormals, 1e-30, +-1e12, +-1e20, +-3e38,
// raw float bits: NaN, infinity). generateProxy must return a proxy or throw proxyvis::Error
// (with a one-line printable message); any other exception, a crash, a sanitizer report or a
// hang is a finding. Sizes are coarse (alpha >= 0.2 of the diagonal, voxels of 1/20, few Hausdorff
// samples) and the time budget is 2 s, so that one execution stays fast.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <typeinfo>

#include "proxies/pipeline/proxy_pipeline.h"
#include "util/error.h"

namespace {

using namespace proxyvis;

// Reads the fuzz bytes front to back; zeros once they run out.
class Bytes {
 public:
  Bytes(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  uint8_t next() { return pos_ < size_ ? data_[pos_++] : 0; }
  float rawFloat() {
    uint32_t bits = 0;
    for (int i = 0; i < 4; ++i) bits = (bits << 8) | next();
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
  }

 private:
  const uint8_t* data_;
  size_t size_, pos_ = 0;
};

// Mostly small grid values (duplicates, collinear and coplanar points are then common), some
// extreme constants, some raw float bit patterns.
float coordinate(Bytes& in) {
  static const float kSpecial[] = {0.0f,   -0.0f,  1e-30f, -1e-30f,        1e-9f, 1e11f,
                                   -1e11f, 1e12f,  -1e12f, 1e13f,          1e20f, -1e20f,
                                   3e38f,  -3e38f, 1e-45f, 1.17549435e-38f};
  const uint8_t selector = in.next();
  if (selector < 200) return float(selector % 16) * 0.25f - 2.0f;
  if (selector < 240) return in.rawFloat();
  return kSpecial[selector % 16];
}

const Triangle kTetraFaces[] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
const Triangle kCubeFaces[] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                               {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};

TriMesh buildMesh(Bytes& in) {
  TriMesh mesh;
  mesh.source = "fuzz.off";
  const uint8_t topology = in.next() % 3;
  const size_t n = 4 + in.next() % 37;  // 4..40 vertices
  for (size_t i = 0; i < n; ++i) {
    const float x = coordinate(in), y = coordinate(in), z = coordinate(in);
    mesh.vertices.emplace_back(x, y, z);
  }
  if (topology == 0) {  // closed: a tetrahedron on the first four vertices
    mesh.triangles.assign(std::begin(kTetraFaces), std::end(kTetraFaces));
  } else if (topology == 1 && n >= 8) {  // closed: a cube's connectivity on the first eight
    mesh.triangles.assign(std::begin(kCubeFaces), std::end(kCubeFaces));
  } else {  // a soup of 1..40 triangles on any vertices
    const size_t faces = 1 + in.next() % 40;
    for (size_t f = 0; f < faces; ++f)
      mesh.triangles.push_back(
          {uint32_t(in.next() % n), uint32_t(in.next() % n), uint32_t(in.next() % n)});
  }
  return mesh;
}

ProxyGenOptions buildOptions(Bytes& in) {
  static const std::pair<ProxyClass, const char*> kMethods[] = {
      {ProxyClass::kOutside, "hull"},   {ProxyClass::kOutside, "wrap"},
      {ProxyClass::kInside, "wrap"},    {ProxyClass::kInside, "erode"},
      {ProxyClass::kGeneral, "qem"},    {ProxyClass::kGeneral, "cgal-sms"},
      {ProxyClass::kGeneral, "meshopt"}};
  const auto& [kind, method] = kMethods[in.next() % 7];
  ProxyGenOptions o;
  o.kind = kind;
  o.method = method;
  o.alpha = 0.2 + 0.1 * (in.next() % 9);      // 0.2 .. 1
  o.offset = 0.01 + 0.01 * (in.next() % 10);  // 0.01 .. 0.1
  o.voxel = 0.05;  // a 22^3 grid: the default 1/150 costs seconds per execution
  o.erosion = 0.05 + 0.05 * (in.next() % 6);
  const uint8_t faces = in.next();
  o.max_faces = faces < 128 ? 0 : 4 + faces % 32;
  o.ratio = 0.1 + 0.1 * (in.next() % 10);
  o.fill_holes = in.next() & 1;
  o.hausdorff_samples = 64;
  o.max_seconds = 2;
  return o;
}

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Bytes in(data, size);
  const ProxyGenOptions options = buildOptions(in);
  const TriMesh mesh = buildMesh(in);
  try {
    const ProxyGenResult result = generateProxy(mesh, options);
    if (result.proxy.empty()) finding("generateProxy returned an empty proxy");
  } catch (const Error& e) {
    // The expected answer to geometry a generator cannot handle: one printable line.
    const std::string message = e.what();
    if (message.empty()) finding("Error with an empty message");
    for (char c : message)
      if (c != '\t' &&
          (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e))
        finding("Error message with a non-printable byte: " + message);
  } catch (const std::exception& e) {
    finding(std::string("exception other than proxyvis::Error (") + typeid(e).name() +
            "): " + e.what());
  }
  return 0;
}
