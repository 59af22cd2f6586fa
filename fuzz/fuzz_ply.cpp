// libFuzzer target: the PLY loader (header check + OpenMesh reader + soup) on arbitrary bytes.
// fuzz-libraries: pv_mesh pv_util
#include "fuzz_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return proxyvis::fuzz::fuzzMeshBytes(data, size, "fuzz.ply");
}
