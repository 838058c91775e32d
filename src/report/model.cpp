#include "report/model.hpp"

#include <cctype>

namespace uabt::report {

std::string ReportInput::verdict_text() const {
  if (!passed()) return "fail";
  int retired = 0, weakened = 0;
  if (uplink)
    for (const ContractChange& c : uplink->contract) {
      if (c.old_holds || c.consent.empty()) continue;
      ++(c.change == "removed" ? retired : weakened);
    }
  const auto count = [](int n, const char* what) {
    return std::to_string(n) + (n == 1 ? " guarantee " : " guarantees ") + what;
  };
  if (retired && weakened)
    return "pass with " + count(retired, "retired") + " and " + std::to_string(weakened) +
           " weakened";
  if (retired) return "pass with " + count(retired, "retired");
  if (weakened) return "pass with " + count(weakened, "weakened");
  return "pass";
}

std::string ReportInput::banner() const {
  std::string out = verdict_text();
  for (std::size_t i = 0; i < out.size() && out[i] != ' '; ++i)
    out[i] = static_cast<char>(std::toupper(static_cast<unsigned char>(out[i])));
  return out;
}

}  // namespace uabt::report
