// The Python module `proxyvis` (docs/python.md): loading, validating and saving meshes, proxy-gen
// and proxy-check on NumPy arrays. Every step is the programs' own library function (mesh/io,
// mesh/validation, proxies/pipeline's generateProxy with proxy-gen's settings, proxies/check's
// checkMeshPair with proxy-check's), so a report equals the program's --json for the same mesh
// and options (timings and file names aside). The GIL is released while they run; errors become
// proxyvis.Error with the message and exit code the programs print and return.
#include <fmt/core.h>
#include <pybind11/eval.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/io/double_reading.h"
#include "mesh/io/mesh_io.h"
#include "mesh/validation.h"
#include "mesh_arrays.h"
#include "proxies/check/check_report.h"
#include "proxies/check/proxy_check_settings.h"
#include "proxies/pipeline/proxy_gen_settings.h"
#include "proxies/pipeline/proxy_pipeline.h"
#include "proxies/pipeline/stage_progress.h"
#include "util/error.h"

namespace py = pybind11;
using namespace proxyvis;
using proxyvis::python::MeshArrays;
using proxyvis::python::prepareMeshArrays;

namespace {

// proxyvis.Error, created at import; lives as long as the interpreter.
PyObject* g_error_type = nullptr;

void raiseError(const std::string& message, int exit_code) {
  py::object type = py::reinterpret_borrow<py::object>(g_error_type);
  py::object error = type(message, exit_code);
  PyErr_SetObject(g_error_type, error.ptr());
}

// JSON as the Python value json.loads gives for the text the programs write.
py::object toPython(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

// --threads as the programs take it: 0 = all cores, at most 4096.
int threadCount(int threads) {
  if (threads < 0 || threads > 4096)
    throw Error("", fmt::format("--threads must be in [0, 4096], got {}", threads),
                "0 uses all cores");
  return threads > 0 ? threads : tbb::info::default_concurrency();
}

// A count given as a Python int (None = `none`), refused below `lo`.
size_t countOf(const std::optional<int64_t>& value, size_t none, int64_t lo, const char* flag) {
  if (!value) return none;
  if (*value < lo) throw Error("", fmt::format("{} must be >= {}, got {}", flag, lo, *value));
  return size_t(*value);
}

// Words of `text` in lines of at most `width` characters, each line starting with `indent`.
std::string wrapped(const std::string& text, const std::string& indent, size_t width = 78) {
  std::istringstream words(text);
  std::string word, line, out;
  while (words >> word) {
    if (!line.empty() && indent.size() + line.size() + 1 + word.size() > width) {
      out += indent + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) out += indent + line + "\n";
  return out;
}

// One parameter of a docstring: its name, then the program's help text indented below it.
std::string param(const std::string& name, const std::string& help) {
  return "    " + name + "\n" + wrapped(help, "        ");
}

// The parameters named after proxy-gen's flags ("max_faces" is --max-faces), each with the
// flag's help text.
std::string proxyGenParams(std::initializer_list<std::string> names) {
  std::string out;
  for (std::string name : names) {
    std::string flag = "--" + name;
    std::replace(flag.begin(), flag.end(), '_', '-');
    out += param(name, proxyGenHelp(flag));
  }
  return out;
}

// ---------------------------------------------------------------------------------------------

py::tuple loadMeshPy(const std::string& path, bool self_intersections,
                     const std::optional<std::string>& mesh_name,
                     const std::optional<std::string>& node_name) {
  GltfPick pick;
  pick.mesh = mesh_name.value_or("");
  pick.node = node_name.value_or("");
  TriMesh mesh;
  std::vector<Vec3d> positions;
  nlohmann::json report;
  {
    py::gil_scoped_release release;
    mesh = loadMesh(path, pick);
    // The file's own numbers: a text format's decimals read in double (rounding each to float
    // gives the mesh's vertices), a binary format's floats. proxy() and check() given these
    // arrays prove classes in the same readings as proxy-gen and proxy-check given the file.
    try {
      positions = readDoublePositions(path, mesh);
    } catch (const Error&) {
      positions.clear();  // the second parser refused the file: the float reading alone
    }
    ValidationOptions validation;
    validation.self_intersections = self_intersections;
    report = toJson(validateMesh(mesh, validation));  // mesh-info --json's entry for the file
    report["file"] = path;
  }
  py::array_t<double> v = python::verticesArray(mesh);
  if (positions.size() == mesh.numVertices()) {
    double* out = v.mutable_data();
    for (size_t i = 0; i < positions.size(); ++i)
      for (int c = 0; c < 3; ++c) out[3 * i + c] = positions[i][c];
  }
  return py::make_tuple(v, python::facesArray(mesh), toPython(report));
}

void saveMeshPy(const std::string& path, const py::object& v, const py::object& f, int draco_bits,
                const std::string& compress, bool ascii) {
  const MeshArrays arrays = prepareMeshArrays(v, f, "V", "F");
  if (draco_bits < 0 || draco_bits > 30)
    throw Error("", fmt::format("--draco-bits must be in [0, 30], got {}", draco_bits));
  SaveOptions save;
  save.draco_quantization = draco_bits;
  save.gltf_compression = parseGltfCompression(compress, path);
  save.binary = !ascii;
  py::gil_scoped_release release;
  saveMesh(arrays.toMesh(), path, save);
}

py::tuple proxyPy(const py::object& v, const py::object& f, const std::string& kind,
                  const std::optional<std::string>& method, const std::optional<int64_t>& max_faces,
                  const std::optional<double>& ratio, int threads, uint64_t seed, bool quiet,
                  const std::optional<double>& alpha, const std::optional<double>& offset,
                  const std::optional<int64_t>& parts, const std::string& budget,
                  double max_seconds, int64_t min_faces, const std::optional<double>& erosion,
                  const std::optional<double>& voxel, const std::optional<double>& clearance,
                  const std::optional<double>& clearance_ulps, bool fill_holes) {
  const MeshArrays arrays = prepareMeshArrays(v, f, "V", "F");
  ProxyGenSettings s;
  s.kind = kind;
  s.method = method.value_or("");
  s.max_faces = countOf(max_faces, 0, 0, "--max-faces");
  s.ratio = ratio;
  s.alpha = alpha;
  s.offset = offset;
  if (parts) s.parts = countOf(parts, 0, 1, "--parts");
  s.budget = budget;
  s.max_seconds = max_seconds;
  s.min_faces = countOf(min_faces, 0, 4, "--min-faces");
  s.erosion = erosion;
  s.voxel = voxel;
  s.clearance = clearance;
  s.clearance_ulps = clearance_ulps;
  s.fill_holes = fill_holes;
  ProxyGenOptions options = proxyGenOptions(s, seed);
  tbb::task_arena arena(threadCount(threads));
  ProxyGenResult result;
  {
    py::gil_scoped_release release;
    std::vector<Vec3d> positions, input_double;
    const TriMesh input = arrays.toMesh(&positions);
    StageProgress progress(quiet, false);
    options.on_stage = [&](const std::string& stage) { progress.stage(stage); };
    // The proof also holds for the float64 numbers given (as for a text file's decimals).
    addDoublePositions(options, input, std::move(positions), input_double);
    arena.execute([&] { result = generateProxy(input, options); });
    progress.done();
  }
  return py::make_tuple(python::verticesArray(result.proxy), python::facesArray(result.proxy),
                        toPython(nlohmann::json(result.report)));
}

py::object checkPy(const py::object& v, const py::object& f, const py::object& vp,
                   const py::object& fp, uint64_t rays, const std::string& distribution,
                   uint64_t seed, const std::optional<std::string>& expect,
                   const std::string& precision, int threads, bool quiet) {
  const MeshArrays original_arrays = prepareMeshArrays(v, f, "V", "F");
  const MeshArrays proxy_arrays = prepareMeshArrays(vp, fp, "Vp", "Fp");
  ProxyCheckSettings s;
  s.rays = rays;
  s.distribution = distribution;
  s.seed = seed;
  s.expect = expect.value_or("");
  s.precision = precision;
  s.quiet = quiet;
  pairCheckOptions(s);  // the settings' errors before any work
  tbb::task_arena arena(threadCount(threads));
  nlohmann::json report;
  {
    py::gil_scoped_release release;
    std::vector<Vec3d> original_double;
    const TriMesh original = original_arrays.toMesh(&original_double);
    const TriMesh proxy = proxy_arrays.toMesh();
    arena.execute([&] { report = toJson(checkMeshPair(original, &original_double, proxy, s)); });
  }
  return toPython(report);
}

// ---------------------------------------------------------------------------------------------

const char* const kErrorClass = R"py(
class Error(Exception):
    """The one exception of proxyvis: what the programs print and the exit code they return.

    message    the one-line message ("FILE: WHAT; WHY (TODO)") the programs print after
               "<program>: error: "
    exit_code  the programs' exit-code category: 1 a check failed (e.g. a hard face budget
               no verified proxy meets), 2 bad input or settings, 3 an output cannot be
               written
    """

    def __init__(self, message, exit_code=2):
        super().__init__(message)
        self.message = message
        self.exit_code = exit_code

    def __reduce__(self):
        return (type(self), (self.message, self.exit_code))
)py";

std::string proxyDoc() {
  std::string out = wrapped(
      "proxy-gen on arrays: builds an outside (hull, wrap), inside (wrap, erode) or general "
      "(qem, cgal-sms, meshopt) proxy of the mesh (V, F), verifies its guarantee exactly and "
      "returns it. Sizes are fractions of the bounding-box diagonal.",
      "");
  out += "\n" + wrapped(
                    "Returns (V', F', report): the proxy's vertices (n x 3 float64) and "
                    "triangles (m x 3 int32), and as a dict the report proxy-gen --json "
                    "writes for the same mesh and options (class, checks, volume_ratio, "
                    "hausdorff, seconds; no load time, output file or hash).",
                    "");
  out += "\n" + wrapped(
                    "Parameters (proxy-gen's flags of the same names, with its defaults; "
                    "None is a flag not given):",
                    "");
  out += param("V, F",
               "The mesh: vertices (n x 3 real numbers; float64 read in place) and "
               "triangles (m x 3 integer indices; int32 read in place).");
  out += proxyGenParams({"kind", "method", "max_faces", "ratio"});
  out += param("threads", "Worker threads (0 = all cores); the result is the same at any count");
  out += param("seed", "Random seed; the same seed gives the same result at any thread count");
  out += param("quiet",
               "No progress bar (proxy-gen's bar of its stages, on stderr when it is a "
               "terminal)");
  out += proxyGenParams({"alpha", "offset", "parts"});
  out += param("budget", proxyGenHelp("--budget") +
                             std::string(" (here: a hard budget not met raises proxyvis.Error "
                                         "with exit_code 1)"));
  out += proxyGenParams({"max_seconds", "min_faces", "erosion", "voxel", "clearance",
                         "clearance_ulps", "fill_holes"});
  out += "\n" + wrapped(
                    "The class is proved for the float32 vertices the programs trace and, "
                    "for outside/inside proxies, also for the float64 numbers of V where "
                    "they differ from those, as proxy-gen does for a text file's decimals "
                    "(checks.containment_double).",
                    "");
  out += "\n" + wrapped(
                    "Raises proxyvis.Error: exit_code 2 for bad arrays or settings, 1 when "
                    "a guarantee or a hard budget is not met.",
                    "");
  return out;
}

std::string checkDoc() {
  std::string out = wrapped(
      "proxy-check on arrays: classifies the proxy (Vp, Fp) against its original (V, F) by "
      "sampled segments (counts HH', HM', MH', MM' with 95 % intervals) and by an exact "
      "containment test (CGAL), and returns the dict proxy-check --json writes for the same "
      "meshes and options (counts, intervals, sampled_class, exact, ok, ...). \"ok\" is false "
      "where proxy-check exits 1.",
      "");
  out += "\nParameters (proxy-check's flags of the same names, with its defaults):\n";
  out += param("V, F",
               "The original: vertices (n x 3 real numbers) and triangles (m x 3 "
               "integer indices). The float64 numbers of V are its double reading.");
  out += param("Vp, Fp", "The proxy, likewise.");
  out += param("rays", proxyCheckHelp("--rays"));
  out +=
      param("distribution", proxyCheckHelp("--distribution") +
                                std::string(" (a mesh pair has no camera or lights: sphere only)"));
  out += param("seed", "Random seed; the same seed gives the same result at any thread count");
  out += param("expect", proxyCheckHelp("--expect") + std::string(" (here: \"ok\" is false)"));
  out += param("precision", proxyCheckHelp("--precision") +
                                std::string(" (here: the float32 rounding of V, its float64 "
                                            "numbers, or both)"));
  out += param("threads", "Worker threads (0 = all cores)");
  out += param("quiet", "No progress bar");
  out += "\nRaises proxyvis.Error (exit_code 2) for bad arrays or settings.";
  return out;
}

}  // namespace

PYBIND11_MODULE(proxyvis, m) {
  m.doc() =
      "proxyvis: geometry proxies of triangle meshes (docs/python.md). The functions run the "
      "same library code as the programs: load_mesh/save_mesh (mesh-info), proxy (proxy-gen), "
      "check (proxy-check). Errors raise proxyvis.Error.";
  m.attr("__version__") = PROXYVIS_VERSION;

  py::dict scope;
  scope["__name__"] = "proxyvis";
  py::exec(kErrorClass, scope);
  py::object error = scope["Error"];
  m.attr("Error") = error;
  g_error_type = error.release().ptr();  // one reference kept for good
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const py::error_already_set&) {
      throw;  // a Python exception on its way through
    } catch (const py::builtin_exception&) {
      throw;  // pybind11's own (TypeError for arguments it cannot convert, ...)
    } catch (const std::exception& e) {
      const ErrorReport report = errorReport(e);
      raiseError(report.message, report.exit_code);
    }
  });

  m.def("load_mesh", &loadMeshPy, py::arg("path"), py::arg("self_intersections") = false,
        py::arg("mesh") = py::none(), py::arg("node") = py::none(),
        R"(Loads a mesh file (.obj .ply .off .drc .gltf .glb) as mesh-info and the programs do.

Returns (V, F, report): V the vertices (n x 3 float64: a text file's decimals
as float64, which round to the float32 vertices the programs use; a binary
file's float32 values), F the triangles (m x 3 int32; polygons fan-
triangulated, vertex order kept), report the validation report mesh-info
--json writes for the file (vertices, faces, closed, manifold, watertight,
genus, volume, boundary_edges, ...) as a dict.

    self_intersections  also count self-intersecting triangle pairs (CGAL;
                        slow on large meshes)
    mesh, node          glTF input: take only the mesh (in its own
                        coordinates) or the node and its children (in world
                        coordinates) with this name

Raises proxyvis.Error (exit_code 2) for a missing, corrupt or unsupported file.)");

  m.def("save_mesh", &saveMeshPy, py::arg("path"), py::arg("V"), py::arg("F"),
        py::arg("draco_bits") = 0, py::arg("compress") = "none", py::arg("ascii") = false,
        R"(Writes the mesh (V, F) to path, the format chosen by the extension (.obj .ply
.off .drc .gltf .glb), as the programs write their outputs: atomically (a
temporary file renamed at the end) with a PATH.sha256 sidecar that loading
verifies. Positions are written as float32.

    draco_bits  .drc, or .gltf/.glb with compress="draco": position
                quantization bits (0 = lossless, default; more moves vertices)
    compress    .gltf/.glb: none, draco (KHR_draco_mesh_compression) or
                meshopt (EXT_meshopt_compression, exact)
    ascii       .ply: ASCII instead of binary

Raises proxyvis.Error: exit_code 2 for bad arrays or an unknown extension,
3 when the file cannot be written (the folder must exist).)");

  const ProxyGenSettings defaults;
  m.def("proxy", &proxyPy, proxyDoc().c_str(), py::arg("V"), py::arg("F"),
        py::arg("kind") = defaults.kind, py::arg("method") = py::none(),
        py::arg("max_faces") = py::none(), py::arg("ratio") = py::none(), py::arg("threads") = 0,
        py::arg("seed") = 0, py::arg("quiet") = true, py::kw_only(), py::arg("alpha") = py::none(),
        py::arg("offset") = py::none(), py::arg("parts") = py::none(),
        py::arg("budget") = defaults.budget, py::arg("max_seconds") = defaults.max_seconds,
        py::arg("min_faces") = int64_t(defaults.min_faces), py::arg("erosion") = py::none(),
        py::arg("voxel") = py::none(), py::arg("clearance") = py::none(),
        py::arg("clearance_ulps") = py::none(), py::arg("fill_holes") = defaults.fill_holes);

  const ProxyCheckSettings check_defaults;
  m.def("check", &checkPy, checkDoc().c_str(), py::arg("V"), py::arg("F"), py::arg("Vp"),
        py::arg("Fp"), py::arg("rays") = check_defaults.rays,
        py::arg("distribution") = check_defaults.distribution, py::arg("seed") = 0,
        py::arg("expect") = py::none(), py::arg("precision") = check_defaults.precision,
        py::arg("threads") = 0, py::arg("quiet") = true);
}
