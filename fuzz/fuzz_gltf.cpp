// libFuzzer target: the glTF JSON (.gltf) loader on arbitrary bytes, buffers as data: URIs (no
// file is read: no folder is given).
// fuzz-libraries: pv_mesh pv_util
#include "fuzz_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return proxyvis::fuzz::fuzzMeshBytes(data, size, "fuzz.gltf");
}
