#pragma once
// Scene JSON laid out as people write it (scenes/*.json): objects one key per line, indented by
// two spaces; arrays of numbers on one line ("eye": [0, 1, 3.9], a 4x4 transform as 16 numbers);
// arrays of such arrays on one line when short (a triangle's three corners); other arrays one
// element per line. Numbers are meant to be read back as floats: a double that holds a float
// exactly prints as the shortest decimal that reads back as that float (0.8, not
// 0.800000011920929, which is what nlohmann's dump prints for the float's double).
#include <nlohmann/json.hpp>
#include <string>

namespace proxyvis::detail {

// The text of `value` (no trailing newline). Valid JSON; keys in the object's own order.
std::string sceneJsonText(const nlohmann::ordered_json& value);

// The shortest decimal that reads back as `v` the way JSON readers read it (as a double, then
// narrowed to float), e.g. "0.8", "16", "1e-05"; finite `v` only.
std::string shortestFloatText(float v);

}  // namespace proxyvis::detail
