#include <set>
#include <stdexcept>
#include <system_error>

#include "base/files.hpp"
#include "report/reports.hpp"
#include "report/text.hpp"

namespace uabt::report {

namespace {

// Each counterexample's scenario as counterexamples/<id>.json; scenarios an earlier run left
// there are removed, so that the directory always describes one run.
void write_counterexamples(const ReportInput& input, const std::filesystem::path& dir) {
  std::set<std::string> written;
  if (input.proofs)
    for (const ProofAnswer& a : input.proofs->answers)
      if (a.counterexample) {
        const std::string name = counterexample_file_name(a.requirement);
        write_file_atomically(dir / name, a.counterexample->scenario);
        written.insert(name);
      }
  std::error_code error;
  if (!std::filesystem::is_directory(dir, error)) return;
  for (const auto& entry : std::filesystem::directory_iterator(dir, error)) {
    const auto name = entry.path().filename().string();
    if (entry.path().extension() == ".json" && !written.count(name))
      remove_output_file(entry.path());
  }
  // Only when empty, and never a link to a directory of the user's.
  if (written.empty() && !std::filesystem::is_symlink(dir, error))
    std::filesystem::remove(dir, error);
}

}  // namespace

void write_reports(const ReportInput& input, const std::filesystem::path& out_dir,
                   const std::string& compiled_xml) {
  // findings.txt reads like the terminal (paths open from where uabt ran), but a report
  // never carries a path of the machine: a mission outside the working directory keeps
  // mission-relative paths.
  TextOptions text;
  if (input.mission != nullptr) text.path_prefix = path_prefix_for(input.mission->dir);
  if (text.path_prefix.starts_with('/')) text.path_prefix.clear();
  write_file_atomically(out_dir / "findings.txt", format_text(input.findings, text));
  write_file_atomically(out_dir / "findings.json", to_json(input));
  write_file_atomically(out_dir / "findings.sarif", to_sarif(input));
  write_file_atomically(out_dir / "junit.xml", to_junit(input));
  write_file_atomically(out_dir / "summary.md", to_markdown(input));
  write_file_atomically(out_dir / "report.html", to_html(input));
  write_counterexamples(input, out_dir / "counterexamples");
  // compiled.xml is the tree to uplink: only a passing gate writes it. A failing one keeps the
  // candidate as compiled.rejected.xml. A tree from an earlier run would sit beside reports
  // that say something else, so the other name is removed.
  const char* const kept = input.passed() ? kCompiledTree : kRejectedTree;
  for (const char* name : {kCompiledTree, kRejectedTree}) {
    const auto path = out_dir / name;
    if (!compiled_xml.empty() && name == kept) {
      write_file_atomically(path, compiled_xml);
      continue;
    }
    remove_output_file(path);
  }
}

}  // namespace uabt::report
