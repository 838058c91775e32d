#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace uabt {

// Why a number as written in any input file does not fit the type uabt reads it as, or "" when
// it fits. A literal without fraction or exponent is an integer and must fit a signed 64-bit
// integer, unless `exact_integers` (a FRETISH expression: the solver reads integers exactly);
// any other literal is a real and must lie within a double's range (an underflow such as
// 1e-400 rounds to zero and is accepted). Text that is not a number is left to the parser.
std::string number_misfit(std::string_view literal, bool exact_integers = false);

}  // namespace uabt
