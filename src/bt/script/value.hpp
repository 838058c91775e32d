#pragma once
#include <cstdint>
#include <string>

#include "base/value.hpp"

namespace uabt::bt::script {

// What a blackboard entry holds and what scripts compute: BT.CPP's Any restricted to the
// types a mission uses. Enum values are strings ('rocks'), as in the compiler's scripts.
// `empty` is an entry that exists but was never given a value (an undefined key).
struct ScriptValue {
  enum class Kind : std::uint8_t { empty, boolean, integer, real, string };
  Kind kind = Kind::empty;
  bool boolean = false;
  std::int64_t integer = 0;
  double real = 0.0;
  std::string text;
  // An integer other than 0 and 1 in an entry BT.CPP types bool: its Any keeps both as int64
  // and Any::copyInto copies the raw integer without changing the entry's type, so the entry
  // stays boolean (a later 0, 1, true or false is a boolean again; a fraction is refused).
  bool bool_entry = false;

  static ScriptValue of_bool(bool b);
  static ScriptValue of_int(std::int64_t i);
  static ScriptValue of_real(double r);
  static ScriptValue of_string(std::string s);

  bool empty() const { return kind == Kind::empty; }
  // Booleans count as numbers (0/1), as BT.CPP's scripting does.
  bool is_number() const {
    return kind == Kind::boolean || kind == Kind::integer || kind == Kind::real;
  }
  bool is_string() const { return kind == Kind::string; }
  double as_double() const;  // for numbers only

  // true/false, 42, 0.5 (a real always shows a '.' or an exponent), text as is.
  std::string to_string() const;
  bool operator==(const ScriptValue& other) const;
};

const char* kind_name(ScriptValue::Kind kind);

// Conversions to and from the shared witness/state value (enum literals become strings).
ScriptValue from_value(const Value& value);
Value to_value(const ScriptValue& value);

}  // namespace uabt::bt::script
