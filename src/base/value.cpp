#include "base/value.hpp"

#include "base/number_text.hpp"

namespace uabt {

Value Value::of_bool(bool b) {
  Value v;
  v.kind = Kind::boolean;
  v.boolean = b;
  return v;
}

Value Value::of_int(std::int64_t i) {
  Value v;
  v.kind = Kind::integer;
  v.integer = i;
  v.real = static_cast<double>(i);
  return v;
}

Value Value::of_real(double r, std::string exact) {
  Value v;
  v.kind = Kind::real;
  v.real = r;
  v.text = std::move(exact);
  return v;
}

Value Value::of_enum(std::string literal) {
  Value v;
  v.kind = Kind::enumeration;
  v.text = std::move(literal);
  return v;
}

std::string Value::to_string() const {
  switch (kind) {
    case Kind::boolean: return boolean ? "true" : "false";
    case Kind::integer: return number_text(integer);
    case Kind::real: return text;
    case Kind::enumeration: return text;
  }
  return {};
}

bool Value::operator==(const Value& other) const {
  if (kind != other.kind) return false;
  switch (kind) {
    case Kind::boolean: return boolean == other.boolean;
    case Kind::integer: return integer == other.integer;
    case Kind::real: return text == other.text;
    case Kind::enumeration: return text == other.text;
  }
  return false;
}

const Value* find_value(const State& state, const std::string& name) {
  for (const auto& [key, value] : state)
    if (key == name) return &value;
  return nullptr;
}

}  // namespace uabt
