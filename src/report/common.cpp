#include "report/common.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace uabt::report::detail {

namespace {

bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// "-12.50" style: optional '-', digits, optional '.' and digits.
bool is_plain_decimal(std::string_view s) {
  if (!s.empty() && s.front() == '-') s.remove_prefix(1);
  const auto dot = s.find('.');
  if (dot == std::string_view::npos) return all_digits(s);
  return all_digits(s.substr(0, dot)) && all_digits(s.substr(dot + 1));
}

std::size_t significant_digits(std::string_view s) {
  if (!s.empty() && s.front() == '-') s.remove_prefix(1);
  std::string digits;
  for (char c : s)
    if (c != '.') digits += c;
  const auto first = digits.find_first_not_of('0');
  if (first == std::string::npos) return 1;
  digits.erase(0, first);
  if (s.find('.') != std::string_view::npos) {
    // Trailing zeros after the point carry no precision.
    const auto last = digits.find_last_not_of('0');
    digits.erase(last + 1);
  }
  return digits.size();
}

bool parse_u64(std::string_view s, std::uint64_t& out) {
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && ptr == s.data() + s.size();
}

// "p/q" → its finite decimal expansion, when q has no prime factors but 2 and 5.
bool fraction_to_decimal(std::string_view text, std::string& decimal) {
  bool negative = false;
  if (!text.empty() && text.front() == '-') {
    negative = true;
    text.remove_prefix(1);
  }
  const auto slash = text.find('/');
  if (slash == std::string_view::npos) return false;
  std::uint64_t p = 0, q = 0;
  if (!parse_u64(text.substr(0, slash), p) || !parse_u64(text.substr(slash + 1), q) || q == 0)
    return false;
  const std::uint64_t g = std::gcd(p, q);
  p /= g;
  q /= g;
  std::uint64_t rest = q;
  while (rest % 2 == 0) rest /= 2;
  while (rest % 5 == 0) rest /= 5;
  if (rest != 1) return false;
  decimal = negative && p != 0 ? "-" : "";
  decimal += std::to_string(p / q);
  unsigned __int128 remainder = p % q;
  if (remainder != 0) decimal += '.';
  // q divides a power of ten, so the division ends; 64 digits bound q = 2^64.
  for (int i = 0; remainder != 0 && i < 80; ++i) {
    remainder *= 10;
    decimal += static_cast<char>('0' + static_cast<int>(remainder / q));
    remainder %= q;
  }
  return remainder == 0;
}

}  // namespace

nlohmann::ordered_json value_json(const Value& value) {
  switch (value.kind) {
    case Value::Kind::boolean: return value.boolean;
    case Value::Kind::integer: return value.integer;
    case Value::Kind::enumeration: return value.text;
    case Value::Kind::real: {
      std::string decimal = value.text;
      if (!is_plain_decimal(decimal) && !fraction_to_decimal(value.text, decimal))
        return value.text;
      // A double holds any decimal of at most 15 significant digits so that it prints back
      // as the same decimal: only then is the number exact.
      if (significant_digits(decimal) > 15) return value.text;
      double number = 0;
      const auto [ptr, ec] =
          std::from_chars(decimal.data(), decimal.data() + decimal.size(), number);
      if (ec != std::errc() || ptr != decimal.data() + decimal.size() || !std::isfinite(number))
        return value.text;
      return number;
    }
  }
  return value.to_string();
}

nlohmann::ordered_json witness_json(const State& state) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& [name, value] : state) out[name] = value_json(value);
  return out;
}

std::string percent(std::uint64_t part, std::uint64_t whole) {
  char buffer[32];
  const double share =
      whole == 0 ? 0.0 : 100.0 * static_cast<double>(part) / static_cast<double>(whole);
  std::snprintf(buffer, sizeof buffer, "%.1f%%", share);
  return buffer;
}

std::string location_text(const SourceLocation& location) {
  std::string out = location.file.empty() ? std::string("<mission>") : location.file;
  if (location.line > 0) {
    out += ":" + std::to_string(location.line);
    if (location.column > 0) out += ":" + std::to_string(location.column);
  }
  return out;
}

std::string camel_case(std::string_view id) {
  std::string out;
  bool upper = true;
  for (char c : id) {
    if (c == '-' || c == '_' || c == '.') {
      upper = true;
      continue;
    }
    out += upper && c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
    upper = false;
  }
  return out;
}

std::uint64_t fnv1a(std::string_view text, std::uint64_t seed) {
  std::uint64_t hash = seed;
  for (unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash;
}

std::string hex64(std::uint64_t value) {
  char buffer[17];
  std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(value));
  return buffer;
}

std::string clean_text(std::string_view text) {
  static constexpr const char* kReplacement = "\xEF\xBF\xBD";
  std::string out;
  out.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      if (c == '\r') {
      } else if ((c < 0x20 && c != '\t' && c != '\n') || c == 0x7f) {
        out += ' ';
      } else {
        out += static_cast<char>(c);
      }
      ++i;
      continue;
    }
    std::size_t length = 0;
    std::uint32_t code = 0;
    if (c >= 0xc2 && c <= 0xdf) {
      length = 2;
      code = c & 0x1f;
    } else if (c >= 0xe0 && c <= 0xef) {
      length = 3;
      code = c & 0x0f;
    } else if (c >= 0xf0 && c <= 0xf4) {
      length = 4;
      code = c & 0x07;
    }
    bool valid = length > 0 && i + length <= text.size();
    for (std::size_t k = 1; valid && k < length; ++k) {
      const auto next = static_cast<unsigned char>(text[i + k]);
      if ((next & 0xc0) != 0x80) valid = false;
      code = (code << 6) | (next & 0x3f);
    }
    // Overlong forms, surrogates, beyond U+10FFFF and XML's non-characters are invalid.
    if (valid &&
        ((length == 3 && code < 0x800) || (length == 4 && code < 0x10000) ||
         (code >= 0xd800 && code <= 0xdfff) || code > 0x10ffff || code == 0xfffe || code == 0xffff))
      valid = false;
    if (valid) {
      out.append(text.substr(i, length));
      i += length;
    } else {
      out += kReplacement;
      ++i;
    }
  }
  return out;
}

std::string html_escape(std::string_view text) {
  const std::string clean = clean_text(text);
  std::string out;
  out.reserve(clean.size());
  for (char c : clean) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string pipeline_stage(std::string_view check_stage) {
  if (check_stage == "fretish" || check_stage == "bt" || check_stage == "load") return "load";
  return std::string(check_stage);
}

bool is_per_adaptable_check(const CheckInfo& check) {
  const std::string_view stage = check.stage;
  const std::string_view id = check.id;
  return stage == "verify" || stage == "conform" || stage == "compile" ||
         (stage == "load" && id.substr(0, 4) == "ref-");
}

std::vector<const CheckInfo*> sorted_catalogue() {
  std::vector<const CheckInfo*> out;
  for (const auto& info : check_catalogue()) out.push_back(&info);
  std::sort(out.begin(), out.end(), [](const CheckInfo* a, const CheckInfo* b) {
    return std::string_view(a->id) < std::string_view(b->id);
  });
  return out;
}

SeverityCounts count_severities(const std::vector<Finding>& findings) {
  SeverityCounts counts;
  for (const auto& f : findings) {
    switch (f.severity) {
      case Severity::error: ++counts.errors; break;
      case Severity::warning: ++counts.warnings; break;
      case Severity::note: ++counts.notes; break;
    }
  }
  return counts;
}

std::string counts_text(const SeverityCounts& counts) {
  auto item = [](std::size_t n, const char* word) {
    return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
  };
  return item(counts.errors, "error") + ", " + item(counts.warnings, "warning") + ", " +
         item(counts.notes, "note");
}

const char* alternative_colour(std::size_t index) {
  static constexpr const char* kPalette[] = {
      "#0072b2", "#e69f00", "#009e73", "#56b4e9", "#cc79a7", "#f0e442",
      "#8c564b", "#9467bd", "#17becf", "#bcbd22", "#a6761d", "#1b9e77",
  };
  return kPalette[index % (sizeof kPalette / sizeof kPalette[0])];
}

std::vector<const fretish::SelectionRequirement*> selections_of(const load::Mission& mission,
                                                                const std::string& adaptable) {
  std::vector<const fretish::SelectionRequirement*> guarded, defaults;
  for (const auto& selection : mission.selections) {
    if (selection.adaptable != adaptable) continue;
    (selection.guard ? guarded : defaults).push_back(&selection);
  }
  guarded.insert(guarded.end(), defaults.begin(), defaults.end());
  return guarded;
}

const fretish::Requirement* find_requirement(const load::Mission& mission, const std::string& id) {
  for (const auto& requirement : mission.requirements)
    if (requirement.id == id) return &requirement;
  return nullptr;
}

std::vector<std::string> adaptables_shown(const ReportInput& input) {
  std::vector<std::string> shown = input.adaptables;
  std::vector<std::string> extra;
  auto note = [&](const std::string& id) {
    if (id.empty()) return;
    if (std::find(shown.begin(), shown.end(), id) != shown.end()) return;
    if (std::find(extra.begin(), extra.end(), id) != extra.end()) return;
    extra.push_back(id);
  };
  for (const auto& coverage : input.coverage) note(coverage.adaptable);
  for (const auto& finding : input.findings) note(finding.adaptable);
  std::sort(extra.begin(), extra.end());
  shown.insert(shown.end(), extra.begin(), extra.end());
  return shown;
}

}  // namespace uabt::report::detail
