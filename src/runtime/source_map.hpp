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

// `text` with every place "compiled.xml:L:C" where a node of `compiled` starts (a tree held in
// memory, which no file holds) as the place that node comes from (source_of): the line of
// mission.xml or of an alternative's file, or the requirement a generated node implements.
// Other text, and a place without a source, stays as it is.
std::string with_source_places(std::string text, const bt::Document& compiled,
                               const load::Mission& mission,
                               const std::vector<compile::TraceEntry>& trace);

}  // namespace uabt::runtime
