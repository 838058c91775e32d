// Where a node of the compiled tree comes from: the line of mission.xml or of an
// alternative's file it was copied from, or the requirement a generated node implements.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "base/location.hpp"
#include "compile/compile.hpp"
#include "load/mission.hpp"

namespace uabt::runtime {

// `tree_path` in Engine::tree_path notation ("MainTree/Fallback/Sequence[0]/Script[1]").
std::optional<SourceLocation> source_of(const std::string& tree_path, const load::Mission& mission,
                                        const std::vector<compile::TraceEntry>& trace);

}  // namespace uabt::runtime
