#pragma once
// The files lib/view3d/CMakeLists.txt compiles in (embed_files.cmake): the vendored three.js
// (vendor/) and the page's script and style (page/).
#include <string_view>

namespace proxyvis::detail {

// The bytes of the embedded file with this name ("three.core.min.js", "view3d.js", "LICENSE");
// empty for a name that was not embedded.
std::string_view view3dAsset(std::string_view name);

}  // namespace proxyvis::detail
