#include "bt/script/value.hpp"

#include <charconv>

#include "base/number_text.hpp"

namespace uabt::bt::script {

ScriptValue ScriptValue::of_bool(bool b) {
  ScriptValue v;
  v.kind = Kind::boolean;
  v.boolean = b;
  return v;
}

ScriptValue ScriptValue::of_int(std::int64_t i) {
  ScriptValue v;
  v.kind = Kind::integer;
  v.integer = i;
  return v;
}

ScriptValue ScriptValue::of_real(double r) {
  ScriptValue v;
  v.kind = Kind::real;
  v.real = r;
  return v;
}

ScriptValue ScriptValue::of_string(std::string s) {
  ScriptValue v;
  v.kind = Kind::string;
  v.text = std::move(s);
  return v;
}

double ScriptValue::as_double() const {
  switch (kind) {
    case Kind::boolean: return boolean ? 1.0 : 0.0;
    case Kind::integer: return static_cast<double>(integer);
    case Kind::real: return real;
    default: return 0.0;
  }
}

std::string ScriptValue::to_string() const {
  switch (kind) {
    case Kind::empty: return "";
    case Kind::boolean: return boolean ? "true" : "false";
    case Kind::integer: return number_text(integer);
    case Kind::real: {
      // A real keeps a point so that it reads back as a real: 50.0, 9.5.
      std::string s = number_text(real);
      if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // n: nan, inf
      return s;
    }
    case Kind::string: return text;
  }
  return "";
}

bool ScriptValue::operator==(const ScriptValue& other) const {
  if (kind != other.kind) return false;
  switch (kind) {
    case Kind::empty: return true;
    case Kind::boolean: return boolean == other.boolean;
    case Kind::integer: return integer == other.integer && bool_entry == other.bool_entry;
    case Kind::real: return real == other.real;
    case Kind::string: return text == other.text;
  }
  return false;
}

const char* kind_name(ScriptValue::Kind kind) {
  switch (kind) {
    case ScriptValue::Kind::empty: return "empty";
    case ScriptValue::Kind::boolean: return "bool";
    case ScriptValue::Kind::integer: return "int";
    case ScriptValue::Kind::real: return "real";
    case ScriptValue::Kind::string: return "string";
  }
  return "?";
}

ScriptValue from_value(const Value& value) {
  switch (value.kind) {
    case Value::Kind::boolean: return ScriptValue::of_bool(value.boolean);
    case Value::Kind::integer: return ScriptValue::of_int(value.integer);
    case Value::Kind::real: return ScriptValue::of_real(value.real);
    case Value::Kind::enumeration: return ScriptValue::of_string(value.text);
  }
  return {};
}

Value to_value(const ScriptValue& value) {
  switch (value.kind) {
    case ScriptValue::Kind::boolean: return Value::of_bool(value.boolean);
    case ScriptValue::Kind::integer: return Value::of_int(value.integer);
    case ScriptValue::Kind::real: return Value::of_real(value.real, number_text(value.real));
    case ScriptValue::Kind::string: return Value::of_enum(value.text);
    case ScriptValue::Kind::empty: break;
  }
  return Value::of_enum("");
}

}  // namespace uabt::bt::script
