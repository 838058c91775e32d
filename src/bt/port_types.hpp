#pragma once
// The C++ type names nodes.xml writes in a port's type=, as BehaviorTree.CPP 4.10 converts
// strings into them (convertFromString) and compares them (demangled typeid names). One table,
// read by the schema generator and by the blackboard checks, so both agree on what a literal
// of a port may be.
#include <string>
#include <vector>

namespace uabt::bt {

// What a literal of a port's type is, for the types BT.CPP converts itself.
enum class PortValue {
  any,               // empty, AnyTypeAllowed, BT::Any: BT.CPP checks nothing
  string,            // std::string in any spelling
  signed_integer,    // int, long, int32_t, …
  unsigned_integer,  // unsigned, size_t, uint64_t, …
  real,              // double, float
  boolean,           // bool
  node_status,       // BT::NodeStatus
  other,             // the robot's own types: its convertFromString decides
};

PortValue port_value(const std::string& type);

// Not AnyTypeAllowed / BT::Any / empty: BT.CPP checks its type.
bool strongly_typed(const std::string& type);
bool is_string_type(const std::string& type);
// Names of one type: "std::string" and "std::__cxx11::basic_string<…>", "int" and "int32_t".
bool same_type(const std::string& a, const std::string& b);
// Whether convertFromString<type>(text) succeeds; true for a type it cannot judge.
bool literal_converts(const std::string& text, const std::string& type);

// The literals convertFromString<bool> and <NodeStatus> accept.
const std::vector<const char*>& boolean_literals();
const std::vector<const char*>& node_status_literals();

}  // namespace uabt::bt
