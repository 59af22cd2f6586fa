// Instance list files: one placement per line, "NAME tx ty tz" or "NAME" followed by 12 or 16
// numbers (row-major 3x4 or 4x4, world = M * [x y z 1]). '#' starts a comment; blank lines are
// skipped. This is the format of shared/data/foliage/ecosys/instances.txt.
#include <charconv>
#include <cmath>
#include <sstream>
#include <unordered_map>

#include "scene/internal/value_ranges.h"
#include "scene/scene_desc.h"
#include "util/atomic_write.h"
#include "util/error.h"
#include "util/input_file.h"
#include "util/quoted_text.h"

namespace proxyvis {

namespace {

[[noreturn]] void failLine(const std::filesystem::path& path, size_t line, const std::string& what,
                           const std::string& why = {}, const std::string& todo = {}) {
  throw Error(path.string() + ":" + std::to_string(line), what, why, todo);
}

// Splits on whitespace after removing a trailing comment.
std::vector<std::string_view> tokenize(std::string_view line) {
  if (auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
  std::vector<std::string_view> tokens;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    size_t j = i;
    while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
    if (j > i) tokens.push_back(line.substr(i, j - i));
    i = j;
  }
  return tokens;
}

bool parseFloat(std::string_view s, float& out) {
  // std::from_chars for float is in libstdc++ 11+; it rejects "nan"/"inf" spelled oddly but
  // accepts "nan" and "inf", which the finiteness check below rejects.
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && ptr == s.data() + s.size() && std::isfinite(out);
}

}  // namespace

std::vector<SceneInstanceDesc> loadInstanceList(const std::filesystem::path& path,
                                                const std::vector<SceneMeshDesc>& meshes) {
  return parseInstanceList(readTextFile(path), path, meshes);
}

std::vector<SceneInstanceDesc> parseInstanceList(const std::string& text,
                                                 const std::filesystem::path& path,
                                                 const std::vector<SceneMeshDesc>& meshes) {
  std::unordered_map<std::string, uint32_t> index;
  for (size_t i = 0; i < meshes.size(); ++i) index.emplace(meshes[i].name, uint32_t(i));

  std::vector<SceneInstanceDesc> out;
  std::istringstream in(text);
  std::string line;
  size_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const auto tokens = tokenize(line);
    if (tokens.empty()) continue;
    const std::string name(tokens[0]);
    auto it = index.find(name);
    if (it == index.end())
      failLine(path, line_no, "unknown mesh " + quoteInput(name),
               "every instance must name a mesh of the scene's \"meshes\" list");
    const size_t n = tokens.size() - 1;
    if (n != 3 && n != 12 && n != 16)
      failLine(
          path, line_no,
          "expected 3 (translation), 12 or 16 (row-major matrix) numbers after the name, found " +
              std::to_string(n));
    std::vector<float> v(n);
    for (size_t i = 0; i < n; ++i)
      if (!parseFloat(tokens[i + 1], v[i]))
        failLine(path, line_no, "bad number " + quoteInput(tokens[i + 1]),
                 "numbers must be finite decimals");
    SceneInstanceDesc inst;
    inst.mesh = it->second;
    if (n == 3) {
      inst.transform = Affine3f::translation({v[0], v[1], v[2]});
    } else {
      if (n == 16 && (v[12] != 0 || v[13] != 0 || v[14] != 0 || v[15] != 1))
        failLine(path, line_no, "the last matrix row must be 0 0 0 1",
                 "only affine transforms are allowed");
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) inst.transform.m[r][c] = v[size_t(r * 4 + c)];
    }
    if (auto problem = detail::transformProblem(inst.transform))
      failLine(path, line_no, problem->what, problem->why, problem->todo);
    out.push_back(inst);
  }
  return out;
}

}  // namespace proxyvis
