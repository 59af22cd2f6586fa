#pragma once
// Words for the report's machine keys, for readers of the HTML page ("samples per pixel", not
// "spp"). The JSON keeps the keys.
#include <string>
#include <string_view>

namespace proxyvis {

// The label of a meta key of a report (or of a column of a meta table); an unknown key reads as
// itself with spaces for underscores.
std::string reportLabel(std::string_view key);

}  // namespace proxyvis
