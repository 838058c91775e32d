#pragma once
#include <map>
#include <random>
#include <set>
#include <string>

namespace uabt::testing {

// What the random mission generators share: the seeded choices, the files they write, and the
// node kinds a mission uses (so a sweep can say which kinds it covered).
class MissionWriter {
 public:
  std::map<std::string, std::string> files;
  std::set<std::string> kinds;  // node kinds used

 protected:
  explicit MissionWriter(unsigned seed) : rng_(seed) {}

  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }

  std::string use(const std::string& kind, std::string xml) {
    kinds.insert(kind);
    return xml;
  }
  std::string wrap(const std::string& kind, const std::string& attrs, const std::string& body) {
    kinds.insert(kind);
    return "<" + kind + attrs + ">" + body + "</" + kind + ">";
  }

 private:
  std::mt19937 rng_;
};

}  // namespace uabt::testing
