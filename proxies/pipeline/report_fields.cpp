#include "proxies/pipeline/report_fields.h"

#include "proxies/pipeline/json_visit.h"

namespace proxyvis {

double readDouble(const Field& f) {
  if (!f.value().is_number())
    f.fail(std::string("expected a number, found ") + f.value().type_name());
  return f.value().get<double>();
}

uint64_t readCount(const Field& f) {
  const nlohmann::json& v = f.value();
  if (!v.is_number_unsigned() && !(v.is_number_integer() && v.get<int64_t>() >= 0))
    f.fail(std::string("expected an integer >= 0, found ") + f.value().type_name());
  return f.value().get<uint64_t>();
}

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
  for (const auto& [key, unused] : object.items()) out[key] = readDouble(f[key.c_str()]);
  return out;
}

}  // namespace proxyvis
