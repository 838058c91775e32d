#include <stdexcept>
#include <system_error>

#include "base/files.hpp"
#include "report/reports.hpp"
#include "report/text.hpp"

namespace uabt::report {

void write_reports(const ReportInput& input, const std::filesystem::path& out_dir,
                   const std::string& compiled_xml) {
  write_file_atomically(out_dir / "findings.txt", format_text(input.findings));
  write_file_atomically(out_dir / "findings.json", to_json(input));
  write_file_atomically(out_dir / "findings.sarif", to_sarif(input));
  write_file_atomically(out_dir / "junit.xml", to_junit(input));
  write_file_atomically(out_dir / "summary.md", to_markdown(input));
  write_file_atomically(out_dir / "report.html", to_html(input));
  const auto compiled = out_dir / "compiled.xml";
  if (!compiled_xml.empty()) {
    write_file_atomically(compiled, compiled_xml);
  } else {
    // A compiled tree from an earlier run would sit beside reports that say it was not built.
    std::error_code error;
    std::filesystem::remove(compiled, error);
    if (error)
      throw std::runtime_error("cannot remove " + compiled.filename().string() + ": " +
                               error.message());
  }
}

}  // namespace uabt::report
