#pragma once
#include <string>
#include <vector>

namespace uabt {

// One entry of checks/: generated at build time from checks/<id>.md.
struct CheckInfo {
  const char* id;
  const char* severity;  // default severity: error | warning | note
  const char* stage;     // fretish | load | bt | verify | conform | runtime
  const char* summary;   // one line
  const char* doc;       // Markdown: why it matters, example, fix
};

const std::vector<CheckInfo>& check_catalogue();
const CheckInfo* find_check(const std::string& id);

}  // namespace uabt
