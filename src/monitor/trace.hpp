#pragma once
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "base/finding.hpp"

namespace uabt::monitor {

// One value of a recorded trace, as JSON wrote it.
struct TraceValue {
  enum class Kind { boolean, number, text } kind = Kind::boolean;
  bool boolean = false;
  double number = 0;
  bool integer = false;  // the JSON number has no fraction or exponent
  std::string text;
};

struct TraceTick {
  std::uint64_t tick = 0;
  int line = 0;
  std::vector<std::pair<std::string, TraceValue>> state;  // what this line sets
};

struct Trace {
  std::vector<TraceTick> ticks;
  std::set<std::string> names;    // every variable the trace sets
  std::set<std::string> strings;  // every string value: names of values, not variables
};

// A recorded trace (DESIGN §10): JSON lines {"tick": t, "state": {"name": value, …}}, one a
// tick, ticks consecutive. A line sets the values it lists; the others keep their value.
// Problems are `trace-invalid` findings naming file, line and column.
std::optional<Trace> read_trace(const std::string& content, const std::string& file,
                                std::vector<Finding>& findings);

}  // namespace uabt::monitor
