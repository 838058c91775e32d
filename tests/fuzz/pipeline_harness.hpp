#pragma once
// The fuzz_pipeline check, shared with test_hardening's replay of its inputs.
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>

#include "fuzz/entry_points.hpp"
#include "gate/gate.hpp"
#include "load/mission.hpp"

namespace uabt::fuzz {

namespace detail {

// A directory under the system's temporary directory, removed with the object.
class TempMission {
 public:
  explicit TempMission(const std::string& name) {
    static std::atomic<int> counter{0};
    root_ = std::filesystem::temp_directory_path() /
            ("uabt-fuzz-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    dir_ = root_ / name;
  }
  ~TempMission() {
    std::error_code ec;
    std::filesystem::remove_all(root_, ec);
  }
  TempMission(const TempMission&) = delete;
  TempMission& operator=(const TempMission&) = delete;

  const std::filesystem::path& dir() const { return dir_; }
  void write(const std::string& path, const std::string& content) const {
    const auto full = dir_ / path;
    std::filesystem::create_directories(full.parent_path());
    std::ofstream(full, std::ios::binary | std::ios::trunc) << content;
  }

 private:
  std::filesystem::path root_, dir_;
};

}  // namespace detail

// The whole gate on a fixed mission (two adaptable nodes, their alternatives) whose
// requirements.fret and domain.fret come from the input: the part before the first line
// "%%" is requirements.fret, the rest domain.fret (absent when there is no such line).
class PipelineHarness {
 public:
  static constexpr std::string_view kSeparator = "\n%%\n";

  PipelineHarness() {
    write("mission.xml",
          "<root BTCPP_format=\"4\" main_tree_to_execute=\"MainTree\">\n"
          "  <BehaviorTree ID=\"MainTree\">\n"
          "    <Sequence>\n"
          "      <Fallback>\n"
          "        <IsInLocation/>\n"
          "        <Adaptable ID=\"navigation\"/>\n"
          "      </Fallback>\n"
          "      <Stop/>\n"
          "      <Adaptable ID=\"exploration\"/>\n"
          "    </Sequence>\n"
          "  </BehaviorTree>\n"
          "</root>\n");
    for (const char* alt : {"on_dust", "on_rocks", "on_sand", "on_mud", "hold_position"})
      write(std::string("alternatives/navigation/") + alt + ".xml", alternative(alt));
    for (const char* alt : {"sand_alternative", "rocks_alternative", "nav_to_base"})
      write(std::string("alternatives/exploration/") + alt + ".xml", alternative(alt));
  }
  const std::filesystem::path& dir() const { return files_.dir(); }

  std::string check(std::string_view data, unsigned timeout_ms = 200) {
    const std::size_t cut = data.find(kSeparator);
    write("requirements.fret", std::string(data.substr(0, cut)));
    std::error_code ec;
    if (cut == std::string_view::npos)
      std::filesystem::remove(dir() / "domain.fret", ec);
    else
      write("domain.fret", std::string(data.substr(cut + kSeparator.size())));

    std::string error;
    std::optional<load::Mission> mission = load::load_mission(dir(), {}, error);
    if (!mission) return "the mission did not load: " + error;
    const bool load_errors = has_errors(mission->findings);
    gate::Options options;
    options.verify.timeout_ms = timeout_ms;
    options.verify.threads = 1;
    options.conform.timeout_ms = timeout_ms;
    const gate::Outcome outcome = gate::run_gate(std::move(*mission), options, "fuzz");
    return check_outcome(outcome, load_errors);
  }

  static std::string check_outcome(const gate::Outcome& outcome, bool load_errors) {
    const auto& findings = outcome.report.findings;
    const bool passed = outcome.passed();
    if (passed && has_errors(findings)) return "the gate passed with an error finding";
    if (passed && load_errors) return "the gate passed a mission that did not load cleanly";
    bool inconclusive = false;
    for (const Finding& f : findings) {
      if (f.location.file.empty() && f.severity == Severity::error)
        return "error finding '" + f.message + "' [" + f.check + "] names no file";
      inconclusive |= f.check == "verification-inconclusive";
    }
    if (inconclusive && passed) return "the gate passed although verification was inconclusive";
    if (passed) {
      if (outcome.compiled_xml.empty()) return "the gate passed without a compiled tree";
      std::vector<Finding> reread;
      if (!bt::parse_document(outcome.compiled_xml, "compiled.xml", reread))
        return "the compiled tree does not parse: " + detail::first_error(reread);
    }
    // The counted coverage and the solver's verdicts describe the same state space.
    for (const auto& cov : outcome.verification.coverage) {
      if (!cov.counted || inconclusive) continue;
      bool node_gap = false, node_overlap = false;
      for (const Finding& f : outcome.verification.findings) {
        if (f.adaptable != cov.adaptable) continue;
        node_gap |= f.check == "guard-gap";
        node_overlap |= f.check == "guard-overlap";
      }
      if ((cov.gap_states > 0) != node_gap)
        return cov.adaptable + ": coverage counts " + std::to_string(cov.gap_states) +
               " gap states but the solver " + (node_gap ? "found" : "did not find") + " a gap";
      if ((cov.overlap_states > 0) != node_overlap)
        return cov.adaptable + ": coverage counts " + std::to_string(cov.overlap_states) +
               " overlap states but the solver " + (node_overlap ? "found" : "did not find") +
               " an overlap";
    }
    return {};
  }

 private:
  static std::string alternative(const std::string& id) {
    return "<root BTCPP_format=\"4\">\n  <BehaviorTree ID=\"" + id +
           "\">\n    <Sequence>\n      <Log message=\"" + id +
           "\"/>\n      <MoveForward/>\n    </Sequence>\n  </BehaviorTree>\n</root>\n";
  }
  void write(const std::string& path, const std::string& content) const {
    files_.write(path, content);
  }

  detail::TempMission files_{"mission"};
};

}  // namespace uabt::fuzz
