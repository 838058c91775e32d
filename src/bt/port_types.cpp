#include "bt/port_types.hpp"

#include <charconv>
#include <cstdint>

namespace uabt::bt {

namespace {

const std::vector<const char*> kBooleans = {"true", "false", "True", "False",
                                            "TRUE", "FALSE", "1",    "0"};
const std::vector<const char*> kStatuses = {"SUCCESS", "FAILURE", "RUNNING", "SKIPPED", "IDLE"};

// The spellings of one type, by the name BT.CPP demangles it to on Linux.
std::string canonical(const std::string& t) {
  if (t.rfind("std::__cxx11::basic_string", 0) == 0 || t == "std::string" || t == "string")
    return "std::string";
  if (t == "int32_t" || t == "std::int32_t") return "int";
  if (t == "uint32_t" || t == "std::uint32_t" || t == "unsigned") return "unsigned int";
  if (t == "int64_t" || t == "std::int64_t") return "long";
  if (t == "uint64_t" || t == "std::uint64_t" || t == "size_t" || t == "std::size_t")
    return "unsigned long";
  if (t == "int8_t" || t == "std::int8_t") return "signed char";
  if (t == "uint8_t" || t == "std::uint8_t") return "unsigned char";
  if (t == "int16_t" || t == "std::int16_t") return "short";
  if (t == "uint16_t" || t == "std::uint16_t") return "unsigned short";
  if (t == "NodeStatus") return "BT::NodeStatus";
  if (t == "AnyTypeAllowed" || t == "BT::AnyTypeAllowed" || t == "Any") return "BT::Any";
  return t;
}

template <typename T>
bool parses_as(const std::string& text) {
  T value{};
  const char* last = text.data() + text.size();
  const auto [end, ec] = std::from_chars(text.data(), last, value);
  return !text.empty() && ec == std::errc() && end == last;
}

bool one_of(const std::string& text, const std::vector<const char*>& list) {
  for (const char* item : list)
    if (text == item) return true;
  return false;
}

}  // namespace

PortValue port_value(const std::string& type) {
  const std::string t = canonical(type);
  if (t.empty() || t == "BT::Any") return PortValue::any;
  if (t == "std::string") return PortValue::string;
  if (t == "int" || t == "short" || t == "signed char" || t == "long" || t == "long long")
    return PortValue::signed_integer;
  if (t == "unsigned int" || t == "unsigned short" || t == "unsigned char" ||
      t == "unsigned long" || t == "unsigned long long")
    return PortValue::unsigned_integer;
  if (t == "double" || t == "float") return PortValue::real;
  if (t == "bool") return PortValue::boolean;
  if (t == "BT::NodeStatus") return PortValue::node_status;
  return PortValue::other;
}

bool strongly_typed(const std::string& type) {
  return port_value(type) != PortValue::any;
}

bool is_string_type(const std::string& type) {
  return port_value(type) == PortValue::string;
}

bool same_type(const std::string& a, const std::string& b) {
  return canonical(a) == canonical(b);
}

bool literal_converts(const std::string& text, const std::string& type) {
  switch (port_value(type)) {
    case PortValue::boolean: return one_of(text, kBooleans);
    case PortValue::node_status: return one_of(text, kStatuses);
    case PortValue::signed_integer: return parses_as<std::int64_t>(text);
    case PortValue::unsigned_integer: return parses_as<std::uint64_t>(text);
    case PortValue::real: return parses_as<double>(text);
    default: return true;  // strings, and the robot's own types
  }
}

const std::vector<const char*>& boolean_literals() {
  return kBooleans;
}
const std::vector<const char*>& node_status_literals() {
  return kStatuses;
}

}  // namespace uabt::bt
