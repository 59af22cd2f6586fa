// libFuzzer target: the glTF binary (.glb) loader on arbitrary bytes: GLB chunks, the JSON
// document, accessors, node graphs and the meshopt/Draco decoders behind them. No file is read
// (an external buffer or image URI is refused: no folder is given).
// fuzz-libraries: pv_mesh pv_util
#include "fuzz_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return proxyvis::fuzz::fuzzMeshBytes(data, size, "fuzz.glb");
}
