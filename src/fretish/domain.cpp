#include "fretish/domain.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "base/text.hpp"

namespace uabt::fretish {

std::optional<double> seconds_per_unit(std::string_view unit) {
  const std::string u = lower_case(unit);
  if (u.empty() || u.rfind("tick", 0) == 0) return std::nullopt;
  if (u == "ms" || u.rfind("milli", 0) == 0) return 1e-3;
  if (u == "us" || u.rfind("micro", 0) == 0) return 1e-6;
  if (u == "min" || u.rfind("minute", 0) == 0) return 60;
  if (u == "h" || u.rfind("hour", 0) == 0) return 3600;
  return 1;  // s, sec, second(s)
}

const char* var_type_name(VarType t) {
  switch (t) {
    case VarType::boolean: return "boolean";
    case VarType::integer: return "integer";
    case VarType::real: return "real";
    case VarType::enumeration: return "enum";
  }
  return "boolean";
}

bool number_is_integer(std::optional<VarType> declared, double number, bool written_integer) {
  if (declared == VarType::real) return false;
  if (declared != VarType::integer) return written_integer;
  // In range first (this also refuses NaN), then whole.
  return written_integer || (number >= -0x1p63 && number < 0x1p63 && std::trunc(number) == number);
}

namespace detail {

void NameIndex::update(const std::vector<Variable>& variables) const {
  if (variables.size() < indexed_) clear();
  for (; indexed_ < variables.size(); ++indexed_) {
    const Variable& v = variables[indexed_];
    names_.try_emplace(v.name, indexed_);
    if (v.type != VarType::enumeration) continue;
    for (const std::string& literal : v.enum_values) {
      auto [it, added] = literals_.try_emplace(literal, indexed_);
      if (!added && it->second != indexed_) it->second = kAmbiguous;
    }
  }
}

std::size_t NameIndex::variable(const std::vector<Variable>& variables,
                                const std::string& name) const {
  std::lock_guard lock(mutex_);
  update(variables);
  auto it = names_.find(name);
  if (it != names_.end() && variables[it->second].name != name) {  // replaced in place
    clear();
    update(variables);
    it = names_.find(name);
  }
  return it == names_.end() ? kNone : it->second;
}

std::size_t NameIndex::enum_owner(const std::vector<Variable>& variables,
                                  const std::string& literal) const {
  std::lock_guard lock(mutex_);
  update(variables);
  const auto it = literals_.find(literal);
  return it == literals_.end() ? kNone : it->second;
}

}  // namespace detail

const Variable* Domain::find(const std::string& name) const {
  const std::size_t k = index_.variable(variables, name);
  return k == detail::NameIndex::kNone ? nullptr : &variables[k];
}

Variable* Domain::find(const std::string& name) {
  const std::size_t k = index_.variable(variables, name);
  return k == detail::NameIndex::kNone ? nullptr : &variables[k];
}

const Variable* Domain::enum_owning(const std::string& literal) const {
  const std::size_t k = index_.enum_owner(variables, literal);
  return k >= detail::NameIndex::kAmbiguous ? nullptr : &variables[k];
}

std::string declaration_text(const Variable& v) {
  switch (v.type) {
    case VarType::boolean: return "boolean " + v.name;
    case VarType::enumeration: {
      std::string out = "enum " + v.name + " in {";
      for (std::size_t i = 0; i < v.enum_values.size(); ++i)
        out += (i == 0 ? "" : ", ") + v.enum_values[i];
      return out + "}";
    }
    case VarType::integer:
    case VarType::real: {
      const bool integer = v.type == VarType::integer;
      if (!v.lower.empty() && !v.upper.empty())
        return (integer ? "integer " : "real ") + v.name + " in [" + v.lower + ", " + v.upper + "]";
      // The grammar's one half-bounded type: an unsigned integer (from a FRET export).
      if (integer && v.lower == "0" && v.upper.empty()) return "unsigned integer " + v.name;
      return (integer ? "integer " : "real ") + v.name;
    }
  }
  return "";
}

namespace {

// Bounds as written may differ in form only ("15" and "15.0" of a real).
bool same_bound(const std::string& a, const std::string& b) {
  if (a.empty() || b.empty()) return a == b;
  return a == b || std::strtod(a.c_str(), nullptr) == std::strtod(b.c_str(), nullptr);
}

}  // namespace

bool same_declaration(const Variable& a, const Variable& b) {
  if (a.type != b.type || !same_bound(a.lower, b.lower) || !same_bound(a.upper, b.upper))
    return false;
  // An enum is its set of literals; the order they are written in means nothing.
  std::vector<std::string> left = a.enum_values, right = b.enum_values;
  std::sort(left.begin(), left.end());
  std::sort(right.begin(), right.end());
  return left == right;
}

}  // namespace uabt::fretish
