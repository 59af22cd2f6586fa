#include "mesh_arrays.h"

#include <fmt/core.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "mesh/io/mesh_io.h"
#include "util/error.h"

namespace py = pybind11;

namespace proxyvis::python {
namespace {

using Float64Array = py::array_t<double, py::array::c_style>;
using Int32Array = py::array_t<int32_t, py::array::c_style>;
using Int64Array = py::array_t<int64_t, py::array::c_style>;
constexpr int kConvert = py::array::c_style | py::array::forcecast;

// `a` converted to T, C-contiguous (a copy), or an Error naming it.
template <class T>
py::array converted(const py::array& a, const std::string& name) {
  py::array c = py::array_t<T, kConvert>::ensure(a);
  if (!c) throw Error(name, "cannot be converted to " + std::string(py::str(py::dtype::of<T>())));
  return c;
}

// Any array-like as a NumPy array (a list of lists becomes one), or an Error naming it.
py::array asArray(py::handle h, const std::string& name) {
  py::array a = py::array::ensure(h);
  if (!a)
    throw Error(name, "not an array",
                fmt::format("got {}", std::string(py::str(py::type::of(h).attr("__name__")))),
                "pass a NumPy array of shape (n, 3)");
  return a;
}

void checkShape(const py::array& a, const std::string& name, const char* rows) {
  if (a.ndim() != 2 || a.shape(1) != 3) {
    std::string shape;
    for (py::ssize_t i = 0; i < a.ndim(); ++i)
      shape += (i ? ", " : "") + std::to_string(a.shape(i));
    if (a.ndim() == 1) shape += ",";
    throw Error(name, fmt::format("shape ({}) is not ({}, 3)", shape, rows),
                "one row of three numbers per " +
                    std::string(rows[0] == 'n' ? "vertex (x, y, z)" : "triangle (three indices)"));
  }
  if (a.shape(0) == 0)
    throw Error(name, "empty array",
                rows[0] == 'n' ? "a mesh needs vertices" : "a mesh needs at least one triangle");
}

std::string dtypeName(const py::array& a) {
  return std::string(py::str(a.dtype()));
}

}  // namespace

MeshArrays prepareMeshArrays(py::handle v, py::handle f, const std::string& v_name,
                             const std::string& f_name) {
  MeshArrays m;
  m.v_name = v_name;
  m.f_name = f_name;
  m.name = v_name + ", " + f_name;
  py::array va = asArray(v, v_name);
  const char vk = va.dtype().kind();
  if (vk != 'f' && vk != 'i' && vk != 'u')
    throw Error(v_name, fmt::format("dtype {} is not a real number type", dtypeName(va)),
                "vertex coordinates are numbers", "pass float64 (or float32, or integers)");
  checkShape(va, v_name, "n");
  m.vertices = py::isinstance<Float64Array>(va) ? va : converted<double>(va, v_name);
  py::array fa = asArray(f, f_name);
  const char fk = fa.dtype().kind();
  if (fk != 'i' && fk != 'u')
    throw Error(f_name, fmt::format("dtype {} is not an integer type", dtypeName(fa)),
                "face entries are vertex indices", "pass int32 (or another integer type)");
  checkShape(fa, f_name, "m");
  if (py::isinstance<Int32Array>(fa) || py::isinstance<Int64Array>(fa))
    m.faces = fa;
  else  // uint64 beyond int64 wraps to negative: out of range
    m.faces = converted<int64_t>(fa, f_name);
  return m;
}

TriMesh MeshArrays::toMesh(std::vector<Vec3d>* doubles) const {
  TriMesh mesh;
  mesh.source = name;
  const size_t n = size_t(vertices.shape(0)), nf = size_t(faces.shape(0));
  if (n > std::numeric_limits<uint32_t>::max())
    throw Error(v_name, fmt::format("{} vertices", n), "a mesh holds at most 2^32 - 1");
  const double* p = static_cast<const double*>(vertices.data());
  mesh.vertices.resize(n);
  if (doubles) doubles->resize(n);
  constexpr double kFloatMax = std::numeric_limits<float>::max();
  for (size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) {
      const double x = p[3 * i + c];
      if (!std::isfinite(x))
        throw Error(v_name, fmt::format("vertex {} has a NaN or infinite coordinate", i),
                    "positions must be finite numbers");
      if (std::fabs(x) > kFloatMax)
        throw Error(v_name, fmt::format("vertex {} has a coordinate beyond float range", i),
                    fmt::format("{:g}; proxyvis stores positions as float", x));
    }
    mesh.vertices[i] = Vec3f(float(p[3 * i]), float(p[3 * i + 1]), float(p[3 * i + 2]));
    if (doubles) (*doubles)[i] = Vec3d(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
  }
  mesh.triangles.resize(nf);
  const bool int32 = faces.itemsize() == 4;
  const void* data = faces.data();
  for (size_t t = 0; t < nf; ++t) {
    for (int c = 0; c < 3; ++c) {
      const int64_t index = int32 ? int64_t(static_cast<const int32_t*>(data)[3 * t + c])
                                  : static_cast<const int64_t*>(data)[3 * t + c];
      if (index < 0 || uint64_t(index) >= n)
        throw Error(
            f_name, "vertex index out of range",
            fmt::format("triangle {} references vertex {} but {} has {}", t, index, v_name, n));
      mesh.triangles[t][c] = uint32_t(index);
    }
  }
  checkMeshContent(mesh, name);  // what every loaded mesh satisfies
  return mesh;
}

py::array_t<double> verticesArray(const TriMesh& mesh) {
  py::array_t<double> v({py::ssize_t(mesh.numVertices()), py::ssize_t(3)});
  double* out = v.mutable_data();
  for (size_t i = 0; i < mesh.numVertices(); ++i)
    for (int c = 0; c < 3; ++c) out[3 * i + c] = double(mesh.vertices[i][c]);
  return v;
}

py::array_t<int32_t> facesArray(const TriMesh& mesh) {
  if (mesh.numVertices() > size_t(std::numeric_limits<int32_t>::max()))
    throw Error(mesh.source, fmt::format("{} vertices", mesh.numVertices()),
                "int32 face indices reach 2^31 - 1");
  py::array_t<int32_t> f({py::ssize_t(mesh.numTriangles()), py::ssize_t(3)});
  int32_t* out = f.mutable_data();
  for (size_t t = 0; t < mesh.numTriangles(); ++t)
    for (int c = 0; c < 3; ++c) out[3 * t + c] = int32_t(mesh.triangles[t][c]);
  return f;
}

}  // namespace proxyvis::python
