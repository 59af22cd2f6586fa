#pragma once
// Random proxy-gen reports for the round-trip tests: every optional key present or not, counts
// over the whole 64-bit range, doubles of every magnitude, strings with quotes, escapes and UTF-8.
#include <cmath>
#include <cstdint>
#include <iterator>
#include <optional>
#include <random>
#include <string>

#include "proxies/pipeline/proxy_report.h"

namespace proxyvis::report_test {

class RandomReports {
 public:
  explicit RandomReports(uint64_t seed) : rng_(seed) {}

  bool coin() { return rng_() & 1; }
  uint64_t count() { return coin() ? rng_() % 1000 : rng_(); }
  double number() {
    switch (rng_() % 4) {
      case 0:
        return double(rng_() % 100);  // integral values print as "2.0" and must stay doubles
      case 1:
        return std::uniform_real_distribution<double>(0, 1)(rng_);
      case 2:
        return std::ldexp(std::uniform_real_distribution<double>(-1, 1)(rng_),
                          int(rng_() % 200) - 100);
      default:
        return -std::uniform_real_distribution<double>(0, 1e6)(rng_);
    }
  }
  std::string text() {
    static const char* pieces[] = {"a", "wrap", " ", "\"", "\\", "\n", "é", "ü", "/", "{}", "0"};
    std::string s;
    for (uint64_t i = 0, n = rng_() % 6; i < n; ++i) s += pieces[rng_() % std::size(pieces)];
    return s;
  }
  template <typename T, typename Make>
  std::optional<T> maybe(Make make) {
    return coin() ? std::optional<T>(make()) : std::nullopt;
  }
  ProxyClass proxyClass() { return ProxyClass(rng_() % 3); }
  // Sets each argument, left to right, to a random value of its type.
  template <typename... T>
  void fill(T&... fields) {
    (set(fields), ...);
  }

  ProxyReport report() {
    ProxyReport r;
    r.input = {text(), count(), coin(), coin(), coin(), count()};
    r.kind = proxyClass();
    r.method = text();
    ProxyParameters& p = r.parameters;
    p.max_faces = count();
    p.fill_holes = coin();
    p.seed = count();
    p.budget = coin() ? "hard" : "soft";
    for (std::optional<double>* v :
         {&p.max_seconds, &p.hull_epsilon, &p.alpha, &p.offset, &p.erosion, &p.voxel, &p.ratio,
          &p.parts_epsilon, &p.clearance, &p.clearance_ulps})
      *v = maybe<double>([&] { return number(); });
    for (std::optional<uint64_t>* v :
         {&p.max_faces_from_ratio, &p.min_faces, &p.max_faces_auto, &p.parts})
      *v = maybe<uint64_t>([&] { return count(); });
    for (uint64_t i = 0, n = rng_() % 4; i < n; ++i) r.seconds[text()] = number();
    r.holes_filled = maybe<uint64_t>([&] { return count(); });
    r.seeds = maybe<uint64_t>([&] { return count(); });
    r.voxels = maybe<uint64_t>([&] { return count(); });
    r.parts = maybe<uint64_t>([&] { return count(); });
    r.faces_before_budget = count();
    for (uint64_t i = 0, n = rng_() % 3; i < n; ++i)
      r.budget_attempts.push_back({text(), number(), count(), coin(), coin(), count(), text()});
    for (uint64_t i = 0, n = rng_() % 4; i < n; ++i)
      r.budget_ladder.push_back(coin() ? LadderEntry{text(), "", 0, false, std::nullopt}
                                       : LadderEntry{std::nullopt, text(), count(), coin(),
                                                     maybe<double>([&] { return number(); })});
    r.budget_fallback = maybe<std::string>([&] { return text(); });
    r.budget_reached = maybe<bool>([&] { return coin(); });
    r.checks = {coin(),
                coin(),
                count(),
                maybe<std::string>([&] { return text(); }),
                maybe<std::string>([&] { return text(); }),
                maybe<std::string>([&] { return text(); }),
                maybe<double>([&] { return number(); }),
                maybe<double>([&] { return number(); }),
                maybe<std::string>([&] { return text(); })};
    r.faces = count();
    r.verified = coin();
    r.written_class = maybe<ProxyClass>([&] { return proxyClass(); });
    r.class_reason = maybe<std::string>([&] { return text(); });
    r.volume_ratio = maybe<double>([&] { return number(); });
    r.hausdorff_proxy_to_original = number();
    r.hausdorff_original_to_proxy = number();
    r.hausdorff = {number(), number(), number()};
    if (coin()) r.written_check = WrittenCheck{text(), text()};
    r.output = maybe<std::string>([&] { return text(); });
    r.output_sha256 = maybe<std::string>([&] { return text(); });
    r.report_html = maybe<std::string>([&] { return text(); });
    return r;
  }

  // A scene mesh: with a proxy, skipped (after loading or not) or failed.
  SceneMeshReport sceneMesh() {
    SceneMeshReport m;
    m.name = maybe<std::string>([&] { return text(); });
    switch (rng_() % 3) {
      case 0:
        m.proxy = report();
        m.cache = maybe<std::string>([&] { return text(); });
        break;
      case 1:
        m.skipped = text();
        m.faces = maybe<uint64_t>([&] { return count(); });
        m.cache = maybe<std::string>([&] { return text(); });
        break;
      default:
        m.error = text();
        break;
    }
    return m;
  }

 private:
  void set(uint64_t& u) { u = count(); }
  void set(double& d) { d = number(); }
  void set(bool& b) { b = coin(); }
  void set(std::string& s) { s = text(); }

  std::mt19937_64 rng_;
};

}  // namespace proxyvis::report_test
