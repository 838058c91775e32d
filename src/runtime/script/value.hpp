#pragma once
#include "bt/script/value.hpp"

namespace uabt::runtime {

// The script language's values (bt/script), as the engine names them.
using bt::script::from_value;
using bt::script::kind_name;
using bt::script::ScriptValue;
using bt::script::to_value;

}  // namespace uabt::runtime
