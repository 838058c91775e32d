// prove's monitor of a property whose parts use FRET's temporal functions (persisted,
// occurred, prevOcc) and FTP: one past-time formula over the single-tick atoms of its parts.
// It must mean what `uabt monitor` and `uabt run` mean (monitor::RequirementMonitor, which
// agrees with FRET's ptExpanded) at every tick, in every scope, condition and timing.
#include <gtest/gtest.h>

#include <random>

#include "fretish/durations.hpp"
#include "fretish/parse.hpp"
#include "monitor/formula.hpp"
#include "monitor/monitor.hpp"
#include "prove/monitor_table.hpp"
#include "prove/property_formula.hpp"

namespace uabt::testing {
namespace {

const std::vector<std::string> kNames = {"m", "c", "p", "s"};

monitor::Resolved resolve(const std::string& name) {
  for (std::size_t i = 0; i < kNames.size(); ++i)
    if (kNames[i] == name) return {monitor::Resolved::Kind::variable, static_cast<int>(i)};
  return {};
}

const std::vector<std::string> kScopes = {
    "",          "in m, ",        "when not in m ", "only in m ",  "after m ",
    "before m ", "only after m ", "only before m ", "while m & c "};
const std::vector<std::string> kConditions = {"", "upon c ", "whenever c ", "upon occurred(1, c) ",
                                              "if FTP | prevOcc(c, p) "};
const std::vector<std::string> kTimings = {"always ",         "never ",       "eventually ",
                                           "within 2 ticks ", "for 2 ticks ", "until s ",
                                           "immediately "};
const std::vector<std::string> kResponses = {"persisted(2, p)",
                                             "occurred(1, c & p)",
                                             "prevOcc(c, p)",
                                             "FTP | p",
                                             "persisted(0, c) xor occurred(2, p)",
                                             "c -> prevOcc(p, persisted(1, s))",
                                             "!(occurred(0, p) <-> persisted(1, p))",
                                             "p"};

monitor::Shape shape_of(const fretish::Requirement& r) {
  const monitor::Classified c = monitor::classify(r);
  EXPECT_TRUE(c.shape) << c.reason;
  return *c.shape;
}

TEST(PropertyFormula, TemporalFunctionsMeanWhatTheMonitorMeansInEveryShape) {
  std::mt19937 rng(24);
  int sentences = 0;
  for (const std::string& scope : kScopes)
    for (const std::string& condition : kConditions)
      for (const std::string& timing : kTimings)
        for (const std::string& response : kResponses) {
          const std::string sentence =
              scope + condition + "the sw shall " + timing + "satisfy " + response;
          fretish::ParseResult parsed =
              fretish::parse_requirements_file("X: " + sentence + "\n", "r.fret");
          fretish::lower_durations(parsed.requirements, {}, parsed.findings);
          ASSERT_EQ(parsed.requirements.size(), 1u) << sentence;
          const fretish::Requirement& r = parsed.requirements[0];
          fretish::ExprPtr mode;
          if (r.scope)
            mode =
                r.scope->condition ? r.scope->condition : fretish::make_identifier(r.scope->mode);
          const prove::PropertyFormula pf = prove::build_property_formula(
              shape_of(r), {mode, r.folded_condition(), r.response, r.timing.stop_condition},
              resolve);
          ASSERT_EQ(pf.unsupported, "") << sentence;
          std::vector<monitor::CompiledExpression> atoms;
          for (const auto& a : pf.atoms) {
            std::string error;
            auto e = monitor::CompiledExpression::compile(*a, resolve, error);
            ASSERT_TRUE(e) << sentence << ": " << error;
            atoms.push_back(std::move(*e));
          }
          const monitor::PastTimeLayout layout(pf.formula, pf.root);
          const prove::MonitorTable table(layout, 4096);
          ASSERT_FALSE(table.failed()) << sentence;
          for (int run = 0; run < 6; ++run) {
            std::string reason;
            auto reference = monitor::RequirementMonitor::compile(r, resolve, reason);
            ASSERT_NE(reference, nullptr) << sentence << ": " << reason;
            auto state = layout.initial();
            std::uint32_t row = 0;
            std::vector<char> scratch;
            const int length = 1 + static_cast<int>(rng() % 16);
            for (int t = 0; t < length; ++t) {
              std::vector<monitor::Val> frame;
              for (std::size_t k = 0; k < kNames.size(); ++k)
                frame.push_back(monitor::Val::of_bool(rng() % 3 != 0));
              const bool expected = reference->step(frame);
              ASSERT_FALSE(reference->failed()) << reference->error();
              bool inputs[prove::MonitorTable::kMaxInputs] = {};
              unsigned bits = 0;
              for (std::size_t k = 0; k < atoms.size(); ++k) {
                std::string error;
                inputs[k] = atoms[k].evaluate_bool(frame, error);
                ASSERT_EQ(error, "");
                bits |= inputs[k] ? 1u << k : 0u;
              }
              // The explicit engine's step and the symbolic engine's table.
              ASSERT_EQ(layout.step(inputs, state, scratch), expected)
                  << sentence << " at tick " << t << " of run " << run;
              ASSERT_EQ(table.now(row, bits), expected) << sentence << " at tick " << t;
              row = table.next(row, bits);
              ASSERT_EQ(table.index_of(state), row) << sentence << " at tick " << t;
            }
          }
          ++sentences;
        }
  EXPECT_EQ(sentences, static_cast<int>(kScopes.size() * kConditions.size() * kTimings.size() *
                                        kResponses.size()));
}

// The scope's own expression reads the temporal functions without $Left$ (FRET's
// pastTemporalConditionsNoBounds): prevOcc there is Y((!p) S (p & q)).
TEST(PropertyFormula, TemporalFunctionsInTheScopeExpression) {
  for (const char* text : {"while prevOcc(c, p) the sw shall always satisfy s",
                           "while persisted(1, m) the sw shall always satisfy s",
                           "only while occurred(2, m) the sw shall within 2 ticks satisfy s",
                           "while FTP | m upon c the sw shall always satisfy s"}) {
    fretish::ParseResult parsed =
        fretish::parse_requirements_file(std::string("X: ") + text + "\n", "r.fret");
    fretish::lower_durations(parsed.requirements, {}, parsed.findings);
    ASSERT_EQ(parsed.requirements.size(), 1u) << text;
    const fretish::Requirement& r = parsed.requirements[0];
    ASSERT_TRUE(r.scope && r.scope->condition) << text;
    const prove::PropertyFormula pf = prove::build_property_formula(
        shape_of(r), {r.scope->condition, r.folded_condition(), r.response, nullptr}, resolve);
    ASSERT_EQ(pf.unsupported, "") << text;
    std::vector<monitor::CompiledExpression> atoms;
    for (const auto& a : pf.atoms) {
      std::string error;
      atoms.push_back(*monitor::CompiledExpression::compile(*a, resolve, error));
    }
    const monitor::PastTimeLayout layout(pf.formula, pf.root);
    std::mt19937 rng(7);
    for (int run = 0; run < 50; ++run) {
      std::string reason;
      auto reference = monitor::RequirementMonitor::compile(r, resolve, reason);
      ASSERT_NE(reference, nullptr) << reason;
      auto state = layout.initial();
      std::vector<char> scratch;
      for (int t = 0; t < 12; ++t) {
        std::vector<monitor::Val> frame;
        for (std::size_t k = 0; k < kNames.size(); ++k)
          frame.push_back(monitor::Val::of_bool(rng() % 2 != 0));
        bool inputs[prove::MonitorTable::kMaxInputs] = {};
        for (std::size_t k = 0; k < atoms.size(); ++k) {
          std::string error;
          inputs[k] = atoms[k].evaluate_bool(frame, error);
        }
        ASSERT_EQ(layout.step(inputs, state, scratch), reference->step(frame))
            << text << " at tick " << t << " of run " << run;
      }
    }
  }
}

// What prove's finite state cannot keep is named: pre* (the value of an earlier tick), and a
// temporal function inside a value.
TEST(PropertyFormula, PreviousValuesAndTemporalValuesAreNamed) {
  const auto why = [](const std::string& response) {
    const fretish::ParseResult parsed = fretish::parse_requirements_file(
        "X: the sw shall always satisfy " + response + "\n", "r.fret");
    const fretish::Requirement& r = parsed.requirements.at(0);
    return prove::build_property_formula(shape_of(r), {nullptr, nullptr, r.response, nullptr},
                                         resolve)
        .unsupported;
  };
  EXPECT_EQ(why("preBool(false, p) | c"),
            "preBool/preInt/preReal read the value of an earlier tick, which prove's finite "
            "state does not keep: not supported by prove");
  EXPECT_EQ(why("ite(persisted(1, p), c, s)"),
            "`ite(persisted(1, p), c, s)` reads an earlier tick inside a value; prove reads "
            "persisted, occurred, prevOcc and FTP under !, &, |, xor, -> and <-> only");
  EXPECT_EQ(why("persisted(1, p) & c"), "");
}

}  // namespace
}  // namespace uabt::testing
