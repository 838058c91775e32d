#pragma once
// "Did you mean": the one rule for which known names a misspelt one is shown, for every stage
// (domain and node names, observables, uplink ids, scenario keys, XML attributes).
#include <cstdint>
#include <string>
#include <vector>

namespace uabt {

// Edits between two names: insertions, deletions, substitutions and swaps of two neighbouring
// characters (OnRokcs → OnRocks is one edit), case-sensitive.
int edit_distance(const std::string& a, const std::string& b);

// The names a misspelt one is checked against, indexed once: a sorted copy walked as a trie,
// so that a query visits only the prefixes within two edits of it, however many names there
// are (a tree of 50,000 named nodes has 150,000 observables).
class NameIndex {
 public:
  NameIndex() = default;
  explicit NameIndex(const std::vector<std::string>& names);

  // The names within two edits of `name` and closer than half the shorter's length (so that
  // short names do not all look alike), closest first, then in the order given. `name`
  // itself and the empty name are never suggested; a name given twice is suggested once; a
  // name over 1,000 characters gets none.
  std::vector<std::string> closest(const std::string& name) const;
  // Every name within two edits of `name` (whatever their lengths), but `name` itself, each with
  // its distance, in the order given.
  std::vector<std::pair<int, std::string>> within_two_edits(const std::string& name) const;
  // "did you mean 'OnRocks'?" / "did you mean 'a' or 'b'?" for up to three of closest(name);
  // "" when there is none.
  std::string did_you_mean(const std::string& name) const;

 private:
  struct Entry {
    std::string name;
    std::uint32_t order;  // its first place in the names given
  };
  std::vector<Entry> sorted_;  // by name, each name once
};

// One query without keeping an index: NameIndex(candidates).closest(name).
std::vector<std::string> closest_names(const std::string& name,
                                       const std::vector<std::string>& candidates);
// NameIndex(candidates).did_you_mean(name).
std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace uabt
