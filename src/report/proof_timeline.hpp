#pragma once
// The timeline of a counterexample as rows of cells (ticks as columns), drawn by the HTML and
// the Markdown writers alike. Not part of the public API (see proofs.hpp).
#include <string>
#include <vector>

#include "report/proofs.hpp"

namespace uabt::report::detail {

enum class CellKind {
  text,     // a value shown as text (a number, an enum literal, the root's status)
  on,       // a boolean that is true
  off,      // a boolean that is false
  running,  // an action that runs during this tick (its events, if any, as text)
  idle,     // an action that does not run during this tick
};

struct TimelineCell {
  CellKind kind = CellKind::text;
  std::string text;
};

enum class RowKind { root, value, action };
const char* row_kind_name(RowKind kind);  // "root", "value", "action"

struct TimelineRow {
  RowKind kind = RowKind::value;
  std::string label;
  std::vector<TimelineCell> cells;  // one per tick of the counterexample
};

// Rows: the root's status, each value the property reads (in its order), then each action in
// the order it first does something.
std::vector<TimelineRow> timeline_of(const ProofCounterexample& cex);

// A counterexample as <article class="cex" id=`id`>: `heading` (HTML), the requirement `a`
// states, its timeline, its notes, the command that replays it (with `replay`: the mission and
// the options to run it with) and its scenario. The Proofs section draws every violated
// guarantee with it, the uplink section every guarantee an uplink breaks.
void counterexample_html(const std::string& id, const std::string& heading, const ProofAnswer& a,
                         const ProofCounterexample& cex, const Proofs* replay, std::string& out);

// CSS of the report page and of the timeline.
const char* page_style();
const char* proofs_style();

// The start of a uabt HTML page through its banner: the title names the command
// ("uabt report: M PASS"), `style` is the page's CSS, `lines` the banner's paragraphs (HTML).
std::string page_head(std::string_view command, const std::string& mission, bool passed,
                      const std::string& verdict, const std::string& style,
                      const std::vector<std::string>& lines);
// The end of a page: <main> closed and a footer naming the tool and the mission, and with
// `explains_checks` where `uabt explain` documents its findings.
std::string page_foot(const std::string& tool_version, const std::string& mission,
                      bool explains_checks);

}  // namespace uabt::report::detail
