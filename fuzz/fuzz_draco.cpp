// libFuzzer target: the Draco (.drc) loader on arbitrary bytes. The Draco library itself is not
// instrumented (Debian's build), so coverage guides the fuzzer only through our checks around it.
// fuzz-libraries: pv_mesh pv_util
#include "fuzz_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return proxyvis::fuzz::fuzzMeshBytes(data, size, "fuzz.drc");
}
