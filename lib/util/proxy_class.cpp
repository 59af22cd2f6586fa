#include "util/proxy_class.h"

#include <nlohmann/json.hpp>

#include "util/json_field.h"

namespace proxyvis {

void to_json(nlohmann::json& j, ProxyClass c) {
  j = proxyClassName(c);
}

void from_json(const nlohmann::json& j, ProxyClass& c) {
  const JsonField f(j);
  const std::optional<ProxyClass> parsed = parseProxyClass(f.asString());
  if (!parsed) f.fail("unknown proxy class", "known: outside, inside, general");
  c = *parsed;
}

}  // namespace proxyvis
