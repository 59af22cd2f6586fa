#pragma once
// Which build produced a file: written into image metadata so that an EXR found later says what
// made it. The text is generated at build time (lib/util/build_info.cmake), so it follows the
// checkout's commit without a reconfigure.
#include <string>

namespace proxyvis {

// "0.1.0" (the project version).
std::string versionText();
// "<git describe --always --dirty> Release", or "unknown Release" outside a git checkout.
std::string buildText();

}  // namespace proxyvis
