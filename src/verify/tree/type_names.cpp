#include "verify/tree/type_names.hpp"

#include <charconv>
#include <cstdint>

namespace uabt::verify::tree {

namespace {

// The spellings of one type, by the name BT.CPP demangles it to on Linux.
std::string canonical(std::string t) {
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
  return t;
}

template <typename T>
bool parses_as(const std::string& text) {
  T value{};
  const char* last = text.data() + text.size();
  const auto [end, ec] = std::from_chars(text.data(), last, value);
  return !text.empty() && ec == std::errc() && end == last;
}

}  // namespace

bool strongly_typed(const std::string& type) {
  return !type.empty() && type != "AnyTypeAllowed" && type != "BT::AnyTypeAllowed" &&
         type != "BT::Any" && type != "Any";
}

bool is_string_type(const std::string& type) {
  return canonical(type) == "std::string";
}

bool same_type(const std::string& a, const std::string& b) {
  return canonical(a) == canonical(b);
}

bool literal_converts(const std::string& text, const std::string& type) {
  const std::string t = canonical(type);
  if (t == "bool")
    return text == "0" || text == "1" || text == "true" || text == "TRUE" || text == "True" ||
           text == "false" || text == "FALSE" || text == "False";
  if (t == "int" || t == "short" || t == "signed char" || t == "long" || t == "long long")
    return parses_as<std::int64_t>(text);
  if (t == "unsigned int" || t == "unsigned short" || t == "unsigned char" ||
      t == "unsigned long" || t == "unsigned long long")
    return parses_as<std::uint64_t>(text);
  if (t == "double" || t == "float") return parses_as<double>(text);
  return true;  // strings, and the robot's own types (its convertFromString decides)
}

}  // namespace uabt::verify::tree
