#include "mesh/io/internal/openmesh_formats.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/exporter/BaseExporter.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <mutex>
#include <sstream>

#include "mesh/io/internal/printable.h"
#include "util/error.h"

namespace proxyvis::detail {
namespace {

namespace OM = OpenMesh;
using OM::EdgeHandle;
using OM::FaceHandle;
using OM::HalfedgeHandle;
using OM::VertexHandle;

// OpenMesh's reader and writer modules are process-wide singletons with per-read member state
// (the PLY reader keeps its property lists in members), so every OpenMesh file access is
// serialized. The same lock guards the redirection of OpenMesh's error stream.
std::mutex& openMeshMutex() {
  static std::mutex m;
  return m;
}

// Collects OpenMesh's diagnostics (normally printed to std::cerr) so they become the "why" of
// our Error instead of stray lines on the terminal, and mutes its progress log ("[OBJWriter] :
// write file"). The error stream's buffer is swapped for ours rather than its targets
// disconnected and connected: OpenMesh's disconnect() drops a target without deleting it, which
// leaked two 16-byte objects per file read (LeakSanitizer, in the fuzz build's mesh-info).
class CapturedOmErr {
 public:
  CapturedOmErr() {
    ::omerr().flush();
    previous_ = ::omerr().rdbuf(captured_.rdbuf());
    log_was_enabled_ = ::omlog().is_enabled();
    out_was_enabled_ = ::omout().is_enabled();
    ::omlog().disable();
    ::omout().disable();
  }
  ~CapturedOmErr() {
    ::omerr().flush();
    ::omerr().rdbuf(previous_);
    if (log_was_enabled_) ::omlog().enable();
    if (out_was_enabled_) ::omout().enable();
  }
  // One line of printable text: OpenMesh quotes what it read (property names, keywords), which
  // in a corrupt file can be any bytes.
  std::string text() {
    ::omerr().flush();
    std::string s = captured_.str();
    for (char& c : s)
      if (c == '\n' || c == '\r') c = ' ';
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return printableExcerpt(s, 200);
  }

 private:
  std::ostringstream captured_;
  std::streambuf* previous_ = nullptr;
  bool log_was_enabled_ = true, out_was_enabled_ = true;
};

// BaseImporter that keeps positions and fan-triangulated faces and ignores everything else
// (normals, colours, texture coordinates, status bits).
class SoupImporter : public OM::IO::BaseImporter {
 public:
  explicit SoupImporter(TriMesh& out) : out_(out) {}

  VertexHandle add_vertex(const OM::Vec3f& p) override {
    out_.vertices.emplace_back(p[0], p[1], p[2]);
    return VertexHandle(int(out_.vertices.size() - 1));
  }
  VertexHandle add_vertex() override { return add_vertex(OM::Vec3f(0, 0, 0)); }
  HalfedgeHandle add_edge(VertexHandle, VertexHandle) override { return HalfedgeHandle(); }
  FaceHandle add_face(const VHandles& vs) override {
    if (vs.size() < 3) {
      ++short_faces_;
      return FaceHandle();
    }
    for (VertexHandle v : vs) {
      if (v.idx() < 0 || size_t(v.idx()) >= out_.vertices.size()) {
        if (bad_index_ == 0) first_bad_index_ = v.idx();
        ++bad_index_;
        return FaceHandle();
      }
    }
    for (size_t i = 1; i + 1 < vs.size(); ++i)
      out_.triangles.push_back(
          {uint32_t(vs[0].idx()), uint32_t(vs[i].idx()), uint32_t(vs[i + 1].idx())});
    return FaceHandle(int(faces_++));
  }
  FaceHandle add_face(HalfedgeHandle) override { return FaceHandle(); }
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<OM::Vec2f>&) override {}
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<OM::Vec3f>&) override {}
  void set_face_texindex(FaceHandle, int) override {}
  void set_point(VertexHandle v, const OM::Vec3f& p) override {
    if (v.idx() >= 0 && size_t(v.idx()) < out_.vertices.size())
      out_.vertices[size_t(v.idx())] = Vec3f(p[0], p[1], p[2]);
  }
  void set_halfedge(VertexHandle, HalfedgeHandle) override {}
  void set_normal(VertexHandle, const OM::Vec3f&) override {}
  void set_normal(VertexHandle, const OM::Vec3d&) override {}
  void set_color(VertexHandle, const OM::Vec3uc&) override {}
  void set_color(VertexHandle, const OM::Vec4uc&) override {}
  void set_color(VertexHandle, const OM::Vec3f&) override {}
  void set_color(VertexHandle, const OM::Vec4f&) override {}
  void set_texcoord(VertexHandle, const OM::Vec2f&) override {}
  void set_status(VertexHandle, const OM::Attributes::StatusInfo&) override {}
  void set_next(HalfedgeHandle, HalfedgeHandle) override {}
  void set_face(HalfedgeHandle, FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(HalfedgeHandle, const OM::Vec2f&) override {}
  void set_texcoord(VertexHandle, const OM::Vec3f&) override {}
  void set_texcoord(HalfedgeHandle, const OM::Vec3f&) override {}
  void set_status(HalfedgeHandle, const OM::Attributes::StatusInfo&) override {}
  void set_color(EdgeHandle, const OM::Vec3uc&) override {}
  void set_color(EdgeHandle, const OM::Vec4uc&) override {}
  void set_color(EdgeHandle, const OM::Vec3f&) override {}
  void set_color(EdgeHandle, const OM::Vec4f&) override {}
  void set_status(EdgeHandle, const OM::Attributes::StatusInfo&) override {}
  void set_normal(FaceHandle, const OM::Vec3f&) override {}
  void set_normal(FaceHandle, const OM::Vec3d&) override {}
  void set_color(FaceHandle, const OM::Vec3uc&) override {}
  void set_color(FaceHandle, const OM::Vec4uc&) override {}
  void set_color(FaceHandle, const OM::Vec3f&) override {}
  void set_color(FaceHandle, const OM::Vec4f&) override {}
  void set_status(FaceHandle, const OM::Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}
  // The header's counts are not trusted (the caller checked them against the file size, but a
  // soup grows as it is read anyway): no reservation.
  void reserve(unsigned int, unsigned int, unsigned int) override {}
  size_t n_vertices() const override { return out_.vertices.size(); }
  size_t n_faces() const override { return faces_; }
  size_t n_edges() const override { return 0; }

  size_t badIndexCount() const { return bad_index_; }
  int firstBadIndex() const { return first_bad_index_; }
  size_t shortFaceCount() const { return short_faces_; }

 private:
  TriMesh& out_;
  size_t faces_ = 0;
  size_t bad_index_ = 0;
  int first_bad_index_ = 0;
  size_t short_faces_ = 0;
};

// BaseExporter over a TriMesh: positions and triangles, nothing else.
class SoupExporter : public OM::IO::BaseExporter {
 public:
  explicit SoupExporter(const TriMesh& m) : m_(m) {}

  OM::Vec3f point(VertexHandle v) const override {
    const Vec3f& p = m_.vertices[size_t(v.idx())];
    return {p.x, p.y, p.z};
  }
  OM::Vec3d pointd(VertexHandle v) const override {
    const OM::Vec3f p = point(v);
    return {p[0], p[1], p[2]};
  }
  bool is_point_double() const override { return false; }
  OM::Vec3f normal(VertexHandle) const override { return {0, 0, 0}; }
  OM::Vec3d normald(VertexHandle) const override { return {0, 0, 0}; }
  bool is_normal_double() const override { return false; }
  OM::Vec3uc color(VertexHandle) const override { return {0, 0, 0}; }
  OM::Vec4uc colorA(VertexHandle) const override { return {0, 0, 0, 0}; }
  OM::Vec3ui colori(VertexHandle) const override { return {0, 0, 0}; }
  OM::Vec4ui colorAi(VertexHandle) const override { return {0, 0, 0, 0}; }
  OM::Vec3f colorf(VertexHandle) const override { return {0, 0, 0}; }
  OM::Vec4f colorAf(VertexHandle) const override { return {0, 0, 0, 0}; }
  OM::Vec2f texcoord(VertexHandle) const override { return {0, 0}; }
  OM::Vec2f texcoord(HalfedgeHandle) const override { return {0, 0}; }
  OM::Attributes::StatusInfo status(VertexHandle) const override { return {}; }
  unsigned int get_vhandles(FaceHandle f, std::vector<VertexHandle>& vs) const override {
    const Triangle& t = m_.triangles[size_t(f.idx())];
    vs.assign({VertexHandle(int(t[0])), VertexHandle(int(t[1])), VertexHandle(int(t[2]))});
    return 3;
  }
  HalfedgeHandle getHeh(FaceHandle, VertexHandle) const override { return HalfedgeHandle(); }
  unsigned int get_face_texcoords(std::vector<OM::Vec2f>&) const override { return 0; }
  OM::Vec3f normal(FaceHandle) const override { return {0, 0, 0}; }
  OM::Vec3d normald(FaceHandle) const override { return {0, 0, 0}; }
  OM::Vec3uc color(FaceHandle) const override { return {0, 0, 0}; }
  OM::Vec4uc colorA(FaceHandle) const override { return {0, 0, 0, 0}; }
  OM::Vec3ui colori(FaceHandle) const override { return {0, 0, 0}; }
  OM::Vec4ui colorAi(FaceHandle) const override { return {0, 0, 0, 0}; }
  OM::Vec3f colorf(FaceHandle) const override { return {0, 0, 0}; }
  OM::Vec4f colorAf(FaceHandle) const override { return {0, 0, 0, 0}; }
  OM::Attributes::StatusInfo status(FaceHandle) const override { return {}; }
  OM::Vec3uc color(EdgeHandle) const override { return {0, 0, 0}; }
  OM::Vec4uc colorA(EdgeHandle) const override { return {0, 0, 0, 0}; }
  OM::Vec3ui colori(EdgeHandle) const override { return {0, 0, 0}; }
  OM::Vec4ui colorAi(EdgeHandle) const override { return {0, 0, 0, 0}; }
  OM::Vec3f colorf(EdgeHandle) const override { return {0, 0, 0}; }
  OM::Vec4f colorAf(EdgeHandle) const override { return {0, 0, 0, 0}; }
  OM::Attributes::StatusInfo status(EdgeHandle) const override { return {}; }
  int get_halfedge_id(VertexHandle) override { return -1; }
  int get_halfedge_id(FaceHandle) override { return -1; }
  int get_next_halfedge_id(HalfedgeHandle) override { return -1; }
  int get_to_vertex_id(HalfedgeHandle) override { return -1; }
  int get_face_id(HalfedgeHandle) override { return -1; }
  OM::Attributes::StatusInfo status(HalfedgeHandle) const override { return {}; }
  size_t n_vertices() const override { return m_.vertices.size(); }
  size_t n_faces() const override { return m_.triangles.size(); }
  size_t n_edges() const override { return 0; }
  bool is_triangle_mesh() const override { return true; }
  // The PLY writer looks up custom properties in the kernel and crashes on nullptr: hand it an
  // empty kernel (no custom properties to write).
  const OM::BaseKernel* kernel() override { return &no_properties_; }

 private:
  const TriMesh& m_;
  OM::BaseKernel no_properties_;
};

}  // namespace

void readWithOpenMesh(const std::string& bytes, const std::string& ext, const std::string& file,
                      TriMesh& out) {
  SoupImporter importer(out);
  std::istringstream in(bytes, std::ios::in | std::ios::binary);
  bool ok = false;
  std::string diagnostics;
  {
    std::lock_guard<std::mutex> lock(openMeshMutex());
    CapturedOmErr captured;
    OM::IO::Options options;  // positions only
    ok = OM::IO::IOManager().read(in, ext, importer, options);
    diagnostics = captured.text();
  }
  if (!ok)
    throw Error(file, "cannot parse the " + ext + " file",
                diagnostics.empty() ? "OpenMesh's " + ext + " reader rejected it"
                                    : "OpenMesh: " + diagnostics,
                "check that the file is a valid " + ext + " mesh (re-export it)");
  if (importer.badIndexCount() > 0)
    throw Error(file, "vertex index out of range",
                std::to_string(importer.badIndexCount()) +
                    " face(s) reference a missing vertex (e.g. " +
                    std::to_string(importer.firstBadIndex()) + "; the file has " +
                    std::to_string(out.vertices.size()) + " vertices)",
                "the file is corrupt; re-export it");
  if (importer.shortFaceCount() > 0)
    throw Error(file, "face with fewer than 3 vertices",
                std::to_string(importer.shortFaceCount()) + " face(s) cannot form a triangle",
                "the file is corrupt; re-export it");
}

bool writeWithOpenMesh(const TriMesh& mesh, const std::string& ext, std::ostream& out,
                       bool binary) {
  SoupExporter exporter(mesh);
  OM::IO::Options options;
  if (binary && ext == "ply") options += OM::IO::Options::Binary;
  std::lock_guard<std::mutex> lock(openMeshMutex());
  CapturedOmErr captured;
  // 9 significant digits round-trip every float exactly in the ASCII formats.
  return OM::IO::IOManager().write(out, ext, exporter, options, 9);
}

}  // namespace proxyvis::detail
