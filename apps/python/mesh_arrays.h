#pragma once
// NumPy arrays <-> TriMesh for the Python module. Arrays are checked for shape and type with the
// GIL held (prepareMeshArrays); their numbers are read into a TriMesh without it (toMesh), with
// the checks every loaded mesh passes (mesh/io/mesh_io.h's checkMeshContent). A C-contiguous
// float64 V and int32 (or int64) F are read in place; other numeric arrays are converted first.
#include <pybind11/numpy.h>

#include <string>
#include <vector>

#include "mesh/tri_mesh.h"
#include "util/vec3.h"

namespace proxyvis::python {

// Two arrays checked to be V (n x 3, real numbers) and F (m x 3, integers), n and m >= 1.
struct MeshArrays {
  pybind11::array vertices;  // float64, C-contiguous
  pybind11::array faces;     // int32 or int64, C-contiguous
  std::string name;          // "V, F": names the mesh in messages and reports
  std::string v_name, f_name;

  // The mesh (float positions, as every program reads a file) and, when `doubles` is given, the
  // positions as the float64 numbers they are. Throws Error (exit code 2) naming the array for a
  // NaN or infinite coordinate, one beyond float range, or a face index out of range. Needs no
  // GIL.
  TriMesh toMesh(std::vector<Vec3d>* doubles = nullptr) const;
};

// Throws Error (exit code 2) naming the argument for anything but two arrays (or nested
// sequences) of shape (n, 3) and (m, 3) with n, m >= 1, real-number V and integer F.
MeshArrays prepareMeshArrays(pybind11::handle v, pybind11::handle f, const std::string& v_name,
                             const std::string& f_name);

// A mesh as the arrays the module returns: V (n x 3 float64), F (m x 3 int32). Needs the GIL.
pybind11::array_t<double> verticesArray(const TriMesh& mesh);
pybind11::array_t<int32_t> facesArray(const TriMesh& mesh);

}  // namespace proxyvis::python
