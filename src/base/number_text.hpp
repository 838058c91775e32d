#pragma once
// The one way uabt writes a number, in every output (text, JSON, Markdown, HTML): the shortest
// text that reads back as the same value, as people write numbers.
#include <cstdint>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "base/value.hpp"

namespace uabt {

// Integers as integers (`50`, `-3`); other numbers with the fewest digits that read back as
// the same double (`9.5`, `0.1`, `-40.5`). Plain digits for magnitudes from 1e-7 up to (not
// including) 1e21, as JSON and JavaScript write them, so an integer-valued double prints as
// an integer (`10000000000`); beyond that range the exponent form (`1e+21`, `2.5e-08`), where
// plain digits would run to more than twenty. `-0` prints as `0`; NaN and infinities as `nan`,
// `inf` and `-inf`.
std::string number_text(double value);
std::string number_text(std::int64_t value);

// A number as a JSON number: an integer-valued double within 64 bits as a JSON integer (`50`,
// not `50.0`), any other finite one as a JSON real; a NaN or infinity (JSON has none) as its
// text.
nlohmann::ordered_json number_json(double value);

// A value (a witness, a state, what a property read) as JSON: booleans as JSON booleans,
// numbers as number_json writes them (a whole real as an integer, `-2`: a reader types a
// number by its variable's declaration, fretish::number_is_integer; a real whose exact value
// is no double, such as the solver's 1/3, as its exact text), enumeration values as strings.
nlohmann::ordered_json value_json(const Value& value);
// A state (a witness, a scenario's initial values) as a JSON object of value_json, in its order.
nlohmann::ordered_json state_json(const State& state);

// A number read at run time (by a monitor, from a trace) as a Value: integer-valued numbers
// within 64 bits are integers, the others reals whose text is number_text's.
Value number_value(double value);

}  // namespace uabt
