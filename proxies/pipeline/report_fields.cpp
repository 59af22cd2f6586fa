#include "proxies/pipeline/report_fields.h"

#include "proxies/pipeline/json_visit.h"

namespace proxyvis {

ProxyClass readAs(const Field& f, Tag<ProxyClass>) {
  const std::optional<ProxyClass> c = parseProxyClass(f.asString());
  if (!c) f.fail("expected outside, inside or general");
  return *c;
}

nlohmann::json readAs(const Field& f, Tag<nlohmann::json>) {
  if (!f.value().is_object())
    f.fail(std::string("expected an object, found ") + f.value().type_name());
  return f.value();
}

std::map<std::string, double> readAs(const Field& f, Tag<std::map<std::string, double>>) {
  const nlohmann::json& object = readAs(f, Tag<nlohmann::json>{});
  std::map<std::string, double> out;
  for (const auto& [key, unused] : object.items()) out[key] = f[key.c_str()].asDouble();
  return out;
}

}  // namespace proxyvis
