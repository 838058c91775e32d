#pragma once
#include <string>
#include <vector>

namespace uabt {

// Edits between two names: insertions, deletions, substitutions and swaps of two neighbouring
// characters (OnRokcs → OnRocks is one edit), case-sensitive.
int edit_distance(const std::string& a, const std::string& b);

// The candidates within two edits of `name` (and closer than half its length, so that short
// names do not all look alike), closest first, then in the order given. `name` itself is
// never suggested.
std::vector<std::string> closest_names(const std::string& name,
                                       const std::vector<std::string>& candidates);

// "did you mean 'OnRocks'?" / "did you mean 'a' or 'b'?"; "" when there is no candidate.
std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace uabt
