#pragma once
// tinygltf as proxyvis compiles it (once, in io/tiny_gltf_impl.cpp, against the system's
// nlohmann-json): no image decoding or encoding, and no image file is ever opened. Debian's
// prebuilt libtinygltf was built with other settings and is not ABI-compatible with its own
// header as we use it, so it is not linked. Every user includes this header, not <tiny_gltf.h>.
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
