#pragma once
// The C++ type names nodes.xml writes in a port's type=, as BehaviorTree.CPP 4.10 converts
// strings into them (convertFromString) and compares them (demangled typeid names).
#include <string>

namespace uabt::verify::tree {

// Not AnyTypeAllowed / BT::Any / empty: BT.CPP checks its type.
bool strongly_typed(const std::string& type);
bool is_string_type(const std::string& type);
// Names of one type: "std::string" and "std::__cxx11::basic_string<…>", "int" and "int32_t".
bool same_type(const std::string& a, const std::string& b);
// Whether convertFromString<type>(text) succeeds; true for a type it cannot judge.
bool literal_converts(const std::string& text, const std::string& type);

}  // namespace uabt::verify::tree
