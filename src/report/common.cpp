#include "report/common.hpp"

#include "base/number_text.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <numeric>

#include "base/text.hpp"

namespace uabt::report::detail {

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

std::string inline_svg(std::string svg) {
  const std::string xmlns = " xmlns=\"http://www.w3.org/2000/svg\"";
  const auto at = svg.find(xmlns);
  if (at != std::string::npos) svg.erase(at, xmlns.size());
  return svg;
}

std::string anchor(std::size_t index, std::string_view id) {
  std::string out = "node-" + std::to_string(index) + "-";
  for (char c : id) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '-' || c == '_';
    out += keep ? c : '_';
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
      case Severity::error: counts.errors += 1 + f.more_like_it; break;
      case Severity::warning: counts.warnings += 1 + f.more_like_it; break;
      case Severity::note: counts.notes += 1 + f.more_like_it; break;
    }
  }
  return counts;
}

std::string counts_text(const SeverityCounts& counts) {
  return count_text(counts.errors, "error") + ", " + count_text(counts.warnings, "warning") + ", " +
         count_text(counts.notes, "note");
}

const char* alternative_colour(std::size_t index) {
  static constexpr const char* kPalette[] = {
      "#0072b2", "#e69f00", "#009e73", "#56b4e9", "#cc79a7", "#f0e442",
      "#8c564b", "#9467bd", "#17becf", "#bcbd22", "#a6761d", "#1b9e77",
  };
  return kPalette[index % (sizeof kPalette / sizeof kPalette[0])];
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

std::string html_code(std::string_view text) {
  return "<code>" + html_escape(text) + "</code>";
}

std::string markdown_text(std::string_view raw) {
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; };
  const std::string text = clean_text(raw);
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    switch (c) {
      case '\n':
      case '\t': out += ' '; break;
      case '_':
        if (i > 0 && i + 1 < text.size() && word(text[i - 1]) && word(text[i + 1]))
          out += c;
        else
          out += "\\_";
        break;
      case '\\':
      case '`':
      case '*':
      case '[':
      case ']':
      case '<':
      case '>':
      case '|':
      case '~':
        out += '\\';
        out += c;
        break;
      case '&':  // only where it could start an entity: "a & b" stays readable
        out += i + 1 < text.size() && (word(text[i + 1]) || text[i + 1] == '#') ? "&amp;" : "&";
        break;
      default: out += c;
    }
  }
  return out;
}

std::string markdown_code(std::string_view raw) {
  const std::string text = clean_text(raw);
  if (text.empty() || text.find_first_of("`|\n") != std::string::npos) return markdown_text(text);
  return "`" + text + "`";
}

std::string alternative_text(const std::string& alternative) {
  return alternative.empty() ? "(nothing: the node fails)" : alternative;
}

}  // namespace uabt::report::detail
