// The one translation unit that holds tinygltf's implementation (see internal/tiny_gltf.h).
#define TINYGLTF_IMPLEMENTATION
#include "mesh/io/internal/tiny_gltf.h"
