#pragma once
// Conform reads ScriptConditions back with the one translation of BT.CPP scripts into
// FRETISH, which the whole-tree checks of verify share.
#include "verify/script_reading.hpp"

namespace uabt::conform {

using verify::parse_script_condition;
using verify::ScriptReading;

}  // namespace uabt::conform
