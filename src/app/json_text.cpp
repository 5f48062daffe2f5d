#include "app/json_text.h"

#include "app/csv.h"

namespace cb {

namespace {

void write(std::string& out, const Json& v) {
  switch (v.type()) {
    case Json::value_t::null:
    case Json::value_t::discarded:
      out += "null";
      return;
    case Json::value_t::boolean:
      out += v.get<bool>() ? "true" : "false";
      return;
    case Json::value_t::number_integer:
      out += std::to_string(v.get<std::int64_t>());
      return;
    case Json::value_t::number_unsigned:
      out += std::to_string(v.get<std::uint64_t>());
      return;
    case Json::value_t::number_float:
      append_number(out, v.get<double>());
      return;
    case Json::value_t::string:
      out += json_string(v.get_ref<const std::string&>());
      return;
    case Json::value_t::array: {
      out += '[';
      bool first = true;
      for (const auto& item : v) {
        if (!first) out += ',';
        first = false;
        write(out, item);
      }
      out += ']';
      return;
    }
    case Json::value_t::object: {
      out += '{';
      bool first = true;
      for (const auto& [key, item] : v.items()) {
        if (!first) out += ',';
        first = false;
        out += json_string(key);
        out += ':';
        write(out, item);
      }
      out += '}';
      return;
    }
    case Json::value_t::binary:
      break;
  }
  out += "null";  // binary values are never built here
}

}  // namespace

std::string json_text(const Json& document) {
  std::string out;
  write(out, document);
  return out;
}

}  // namespace cb
