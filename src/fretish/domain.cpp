#include "fretish/domain.hpp"

#include <algorithm>

namespace uabt::fretish {

const char* var_type_name(VarType t) {
  switch (t) {
    case VarType::boolean: return "boolean";
    case VarType::integer: return "integer";
    case VarType::real: return "real";
    case VarType::enumeration: return "enum";
  }
  return "boolean";
}

const Variable* Domain::find(const std::string& name) const {
  for (const Variable& v : variables)
    if (v.name == name) return &v;
  return nullptr;
}

Variable* Domain::find(const std::string& name) {
  for (Variable& v : variables)
    if (v.name == name) return &v;
  return nullptr;
}

const Variable* Domain::enum_owning(const std::string& literal) const {
  const Variable* owner = nullptr;
  for (const Variable& v : variables) {
    if (v.type != VarType::enumeration) continue;
    if (std::find(v.enum_values.begin(), v.enum_values.end(), literal) == v.enum_values.end())
      continue;
    if (owner != nullptr) return nullptr;  // ambiguous: more than one enum has it
    owner = &v;
  }
  return owner;
}

}  // namespace uabt::fretish
