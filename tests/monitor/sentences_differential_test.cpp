// FRETISH as written: every scope, condition and timing phrase goes through the parser,
// FRET's classification and the monitor, and must give FRET's formula for its key at every tick.
#include <gtest/gtest.h>

#include <random>
#include <regex>
#include <tuple>

#include "fretish/parse.hpp"
#include "monitor/monitor.hpp"
#include "monitor/property_check.hpp"
#include "monitor_test_support.hpp"

namespace uabt::testing {
namespace {

struct Phrase {
  std::string text;
  std::string key;
};

const std::vector<Phrase> kScopes = {
    {"", "null"},
    {"in m, ", "in"},
    {"during m ", "in"},
    {"when in m ", "in"},
    {"if in mode m ", "in"},
    {"in m mode ", "in"},
    {"while m ", "in"},
    {"when not in m ", "notin"},
    {"if not in m ", "notin"},
    {"unless in m ", "notin"},
    {"except in m ", "notin"},
    {"except while m ", "notin"},
    {"only in m ", "onlyIn"},
    {"only during m ", "onlyIn"},
    {"only while m ", "onlyIn"},
    {"after m ", "after"},
    {"before m ", "before"},
    {"only after m ", "onlyAfter"},
    {"only before m ", "onlyBefore"},
};

const std::vector<Phrase> kConditions = {
    {"", "null"},
    {"upon c ", "regular"},
    {"when c, ", "regular"},
    {"if c is true ", "regular"},
    {"where c ", "regular"},
    {"unless c is false ", "regular"},
    {"whenever c ", "holding"},
};

const std::vector<Phrase> kTimings = {
    {"immediately ", "immediately"},
    {"initially ", "immediately"},
    {"at the first timepoint ", "immediately"},
    {"at the same timepoint ", "immediately"},
    {"at the next timepoint ", "next"},
    {"eventually ", "eventually"},
    {"", "null"},
    {"finally ", "finally"},
    {"at the last timepoint ", "finally"},
    {"always ", "always"},
    {"never ", "never"},
    {"within 3 ticks ", "within"},
    {"for 3 ticks ", "for"},
    {"after 3 ticks ", "after"},
    {"until s ", "until"},
    {"before s ", "before"},
};

monitor::Resolved resolve(const std::string& name) {
  static const std::vector<std::string> names = {"m", "c", "p", "s"};
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return {monitor::Resolved::Kind::variable, static_cast<int>(i)};
  return {};
}

TEST(MonitorSemantics, EveryPhraseMeansItsFretTemplate) {
  if (!std::filesystem::exists(fret_reference("semantics.json"))) GTEST_SKIP() << "no FRET data";
  const nlohmann::json semantics = fret_semantics();
  std::mt19937 rng(3);
  std::uniform_int_distribution<std::size_t> length(1, 20);
  int checked = 0;
  for (const Phrase& scope : kScopes) {
    for (const Phrase& condition : kConditions) {
      for (const Phrase& timing : kTimings) {
        const std::string sentence =
            scope.text + condition.text + "the sw shall " + timing.text + "satisfy p";
        const fretish::ParseResult parsed = parse_lowered("X: " + sentence + "\n");
        ASSERT_EQ(parsed.requirements.size(), 1u) << sentence;
        std::string reason;
        auto monitor =
            monitor::RequirementMonitor::compile(parsed.requirements[0], resolve, reason);
        ASSERT_NE(monitor, nullptr) << sentence << ": " << reason;
        const std::string key =
            scope.key + "," + condition.key + "," + timing.key + ",satisfaction";
        EXPECT_EQ(std::string(monitor::scope_key(monitor->shape().scope)) + "," +
                      monitor::condition_key(monitor->shape().condition),
                  scope.key + "," + condition.key)
            << sentence;
        const PtFormula oracle = PtFormula::parse(instantiate(
            semantics.at(key).at("ptExpanded").get<std::string>(), {{"scope_mode", "m"},
                                                                    {"regular_condition", "c"},
                                                                    {"post_condition", "p"},
                                                                    {"stop_condition", "s"},
                                                                    {"duration", "3"}}));
        for (int i = 0; i < 12; ++i) {
          const auto trace = random_boolean_trace(rng, {"m", "c", "p", "s"}, length(rng));
          const std::vector<bool> expected = oracle.evaluate(trace);
          auto run = monitor::RequirementMonitor::compile(parsed.requirements[0], resolve, reason);
          for (std::size_t t = 0; t < trace.size(); ++t) {
            std::vector<monitor::Val> frame;
            for (const char* n : {"m", "c", "p", "s"})
              frame.push_back(monitor::Val::of_bool(trace[t].at(n).truth));
            const bool got = run->step(frame);
            ASSERT_FALSE(run->failed()) << run->error();
            ASSERT_EQ(got, expected[t]) << sentence << " at tick " << t << "\n"
                                        << trace_text(trace);
          }
        }
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, static_cast<int>(kScopes.size() * kConditions.size() * kTimings.size()));
}

// FRET's own rewrite of a condition or response before it formalizes it
// (SemanticsAnalyzer.js, enterPre_condition / enterPost_condition): the field's text in
// parentheses, ` then ` made `=>` and `if` dropped; FRET's LTL.g4 precedence then applies.
// Then FRET's temporal functions become past-time formulas (xform.js, pastTemporalConditions),
// counted from the scope's left end point `left` (semantics.json, endpoints.SMVptExtleft).
std::string fret_rewrite(const std::string& field, const std::string& left = "(!(Y TRUE))") {
  const std::regex then_word(" then ", std::regex::icase);
  const std::regex if_word("(\\(| )(if )", std::regex::icase);
  std::string out =
      std::regex_replace(std::regex_replace("(" + field + ")", then_word, " => "), if_word, "$1");
  // n = 0 gives FRET's H[<0], which holds: nothing lies at a distance below 0.
  const std::regex persisted("persisted\\(([0-9]+), ([^(),]+)\\)");
  const std::regex occurred("occurred\\(([0-9]+), ([^(),]+)\\)");
  const std::regex prev_occ("prevOcc\\(([^(),]+), ([^(),]+)\\)");
  std::smatch m;
  while (std::regex_search(out, m, persisted)) {
    const std::string n = m[1], p = m[2];
    const std::string below = n == "0" ? "TRUE" : "(H[<" + n + "] ! " + left + ")";
    out = m.prefix().str() + "((H[<=" + n + "] (" + p + ")) & " + below + ")" + m.suffix().str();
  }
  out = std::regex_replace(out, occurred, "(((! " + left + ") S ($2)) & (O[<=$1] ($2)))");
  out = std::regex_replace(out, prev_occ,
                           "(" + left + " | (Y (((! " + left + " & !($1)) S ($1)) => ((! " + left +
                               " & !($1)) S (($1) & ($2))))))");
  return out;
}

// Random FRETISH expressions over booleans c, d, integers i, j and the real x, in FRET's
// spelling and without extra parentheses, so that precedence, `if … then` inside expressions,
// signed numbers under `^`, and integer `/` and `mod` all decide the verdict.
class ExpressionMaker {
 public:
  explicit ExpressionMaker(std::mt19937& rng) : rng_(rng) {}

  std::string boolean(int depth) {
    switch (depth <= 0 ? pick(3) : pick(9)) {
      case 0: return pick(2) ? "c" : "d";
      case 1: return pick(2) ? "true" : "false";
      case 2:
      case 3: return relation(depth - 1);
      case 4: return "!(" + boolean(depth - 1) + ")";
      case 5: {
        static const char* const ops[] = {" & ", " | ", " xor ", " -> ", " <-> "};
        return boolean(depth - 1) + ops[pick(5)] + boolean(depth - 1);
      }
      case 6: {
        // FRET drops only an `if ` that follows a space or '(', so `if if` is not FRETISH.
        std::string antecedent = boolean(depth - 1);
        if (antecedent.rfind("if ", 0) == 0) antecedent = "(" + antecedent + ")";
        return "if " + antecedent + " then " + boolean(depth - 1);
      }
      case 7: return temporal();
      default: return "(" + boolean(depth - 1) + ")";
    }
  }

 private:
  // FRET's past-time functions over small arguments (no parentheses, so that fret_rewrite
  // can expand them as FRET does).
  std::string temporal() {
    static const char* const args[] = {"c", "d", "!c", "i > j", "x <= 0.5", "i = 0"};
    const std::string p = args[pick(6)], q = args[pick(6)];
    switch (pick(3)) {
      case 0: return "persisted(" + std::to_string(pick(4)) + ", " + p + ")";
      case 1: return "occurred(" + std::to_string(pick(4)) + ", " + p + ")";
      default: return "prevOcc(" + p + ", " + q + ")";
    }
  }

  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }

  std::string relation(int depth) {
    static const char* const ops[] = {" < ", " <= ", " = ", " != ", " > ", " >= "};
    const bool integer = pick(2) == 0;
    return numeric(depth, integer) + ops[pick(6)] + numeric(depth, integer);
  }

  std::string atom(bool integer) {
    static const char* const ints[] = {"i", "j", "i", "j", "0", "2", "3", "-1", "-2"};
    static const char* const reals[] = {"x", "x", "0.5", "-1.5", "i", "2"};
    return integer ? ints[pick(9)] : reals[pick(6)];
  }

  std::string numeric(int depth, bool integer) {
    if (depth <= 0) return atom(integer);
    static const char* const int_divisors[] = {"2", "3", "-2"};
    static const char* const real_divisors[] = {"2", "0.5", "-2.5"};
    switch (pick(9)) {
      case 0: return numeric(depth - 1, integer) + " + " + numeric(depth - 1, integer);
      case 1: return numeric(depth - 1, integer) + " - " + numeric(depth - 1, integer);
      case 2: return numeric(depth - 1, integer) + " * " + numeric(depth - 1, integer);
      case 3:
        return numeric(depth - 1, integer) + " / " +
               (integer ? int_divisors[pick(3)] : real_divisors[pick(3)]);
      case 4:
        if (integer) return numeric(depth - 1, true) + " mod " + int_divisors[pick(3)];
        return numeric(depth - 1, false) + " / " + real_divisors[pick(3)];
      case 5: return atom(integer) + " ^ 2";
      case 6: return "- " + numeric(depth - 1, integer);
      case 7: return "(" + numeric(depth - 1, integer) + ")";
      default: return atom(integer);
    }
  }

  std::mt19937& rng_;
};

monitor::Resolved resolve_typed(const std::string& name) {
  static const std::vector<std::string> names = {"m", "c", "d", "s", "i", "j", "x"};
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return {monitor::Resolved::Kind::variable, static_cast<int>(i)};
  return {};
}

// A trace of m, c, d, s (booleans), i, j (integers in [-4, 4]) and x (a real).
std::vector<OracleState> random_typed_trace(std::mt19937& rng, std::size_t length) {
  auto trace = random_boolean_trace(rng, {"m", "c", "d", "s"}, length);
  std::uniform_int_distribution<int> small(-4, 4);
  static const double reals[] = {-2.5, -1.5, -0.5, 0, 0.5, 1, 2, 3.5};
  std::uniform_int_distribution<int> real_index(0, 7);
  for (auto& state : trace) {
    state["i"] = OracleValue{true, false, static_cast<double>(small(rng)), true};
    state["j"] = OracleValue{true, false, static_cast<double>(small(rng)), true};
    state["x"] = OracleValue{true, false, reals[real_index(rng)], false};
  }
  return trace;
}

// Every scope, condition and timing, with generated conditions and responses: the monitor's
// verdict equals FRET's formula for the sentence (its template, filled with the fields as FRET
// rewrites them) at every tick.
TEST(MonitorSemantics, GeneratedExpressionsMeanWhatFretFormalizes) {
  if (!std::filesystem::exists(fret_reference("semantics.json"))) GTEST_SKIP() << "no FRET data";
  const nlohmann::json semantics = fret_semantics();
  std::mt19937 rng(24);
  std::uniform_int_distribution<std::size_t> length(1, 14);
  ExpressionMaker make(rng);
  int sentences = 0, verdicts = 0, disagreements = 0, temporal = 0;
  std::string first;
  for (const Phrase& scope : kScopes) {
    for (const Phrase& condition : kConditions) {
      for (const Phrase& timing : kTimings) {
        for (int variant = 0; variant < 2; ++variant) {
          const std::string cond = make.boolean(3), response = make.boolean(3);
          std::string phrase = condition.text;
          if (const auto at = phrase.find(" c"); at != std::string::npos)
            phrase.replace(at, 2, " " + cond);
          const std::string sentence =
              scope.text + phrase + "the sw shall " + timing.text + "satisfy " + response;
          const fretish::ParseResult parsed = parse_lowered("X: " + sentence + "\n");
          ASSERT_EQ(parsed.requirements.size(), 1u) << sentence;
          const std::string key =
              scope.key + "," + condition.key + "," + timing.key + ",satisfaction";
          const std::string left =
              instantiate(semantics.at(key).at("endpoints").at("SMVptExtleft").get<std::string>(),
                          {{"scope_mode", "m"}});
          const std::string formula =
              instantiate(semantics.at(key).at("ptExpanded").get<std::string>(),
                          {{"scope_mode", "m"},
                           {"regular_condition", fret_rewrite(cond, left)},
                           {"post_condition", fret_rewrite(response, left)},
                           {"stop_condition", "s"},
                           {"duration", "3"}});
          const PtFormula oracle = PtFormula::parse(formula);
          ++sentences;
          if (std::regex_search(sentence, std::regex("persisted|occurred|prevOcc"))) ++temporal;
          for (int k = 0; k < 6; ++k) {
            const auto trace = random_typed_trace(rng, length(rng));
            const std::vector<bool> expected = oracle.evaluate(trace);
            std::string reason;
            auto run =
                monitor::RequirementMonitor::compile(parsed.requirements[0], resolve_typed, reason);
            ASSERT_NE(run, nullptr) << sentence << ": " << reason;
            for (std::size_t t = 0; t < trace.size(); ++t) {
              std::vector<monitor::Val> frame;
              for (const char* n : {"m", "c", "d", "s"})
                frame.push_back(monitor::Val::of_bool(trace[t].at(n).truth));
              for (const char* n : {"i", "j"})
                frame.push_back(monitor::Val::of_integer(trace[t].at(n).number));
              frame.push_back(monitor::Val::of_number(trace[t].at("x").number));
              const bool got = run->step(frame);
              ++verdicts;
              if (run->failed() || got != expected[t]) {
                if (disagreements++ == 0)
                  first = sentence + "\nFRET: " + formula + "\ntick " + std::to_string(t) +
                          (run->failed() ? ": " + run->error() : "") + "\n" + trace_text(trace);
                break;
              }
            }
          }
        }
      }
    }
  }
  RecordProperty("sentences", sentences);
  RecordProperty("verdicts", verdicts);
  RecordProperty("temporal_sentences", temporal);
  EXPECT_EQ(disagreements, 0) << disagreements << " disagreements in " << verdicts
                              << " verdicts of " << sentences << " sentences; the first:\n"
                              << first;
  EXPECT_EQ(sentences, static_cast<int>(2 * kScopes.size() * kConditions.size() * kTimings.size()));
  EXPECT_GT(temporal, sentences / 4) << "too few sentences use persisted, occurred or prevOcc";
}

// FRET's own past-time formulas for its temporal functions, from its test suite
// (fret-electron/test/semantics/temporal.js: the ptExpanded of "In mode m the sw shall always
// satisfy persisted(42,p) <=> r" and its after/before and occurred variants, there with
// O[<=42] written O[0,42]), with 42 made 3 and 41 made 2.
TEST(MonitorSemantics, TemporalFunctionsMeanFretsOwnFormulas) {
  struct Case {
    std::string sentence, formula;
  };
  const std::vector<Case> cases = {
      {"in m the sw shall always satisfy persisted(3, p) <-> r",
       "(H (m -> (((H[0,3] p) & (H[0,2] (! (m & ((!(Y TRUE)) | (Y (!m))))))) <-> r)))"},
      {"after m the sw shall always satisfy persisted(3, p) <-> r",
       "((O (((! m) & (Y m)) & (Y (H (! ((! m) & (Y m))))))) -> ((((H[0,3] p) & (H[0,2] (! "
       "(((!m) & (Y m)) & (Y (H (!((!m) & (Y m))))))))) <-> r) S ((((H[0,3] p) & (H[0,2] (! "
       "(((!m) & (Y m)) & (Y (H (!((!m) & (Y m))))))))) <-> r) & (((! m) & (Y m)) & (Y (H (! "
       "((! m) & (Y m)))))))))"},
      {"before m the sw shall always satisfy persisted(3, p) <-> r",
       "((H ((((m & ((! (Y TRUE)) | (Y (! m)))) & ((Y (H (! m))) | (! (Y TRUE)))) & (Y TRUE)) "
       "-> (Y (H (((H[0,3] p) & (H[0,2] (! (!(Y TRUE))))) <-> r))))) & ((H (! ((m & ((! (Y "
       "TRUE)) | (Y (! m)))) & ((Y (H (! m))) | (! (Y TRUE)))))) -> (H (((H[0,3] p) & (H[0,2] "
       "(! (!(Y TRUE))))) <-> r))))"},
      {"in m the sw shall always satisfy occurred(3, p) <-> r",
       "(H (m -> ((((! (m & ((!(Y TRUE)) | (Y (!m))))) S p) & (O[0,3] p)) <-> r)))"},
      {"after m the sw shall always satisfy occurred(3, p) <-> r",
       "((O (((! m) & (Y m)) & (Y (H (! ((! m) & (Y m))))))) -> (((((! (((!m) & (Y m)) & (Y (H "
       "(!((!m) & (Y m))))))) S p) & (O[0,3] p)) <-> r) S (((((! (((!m) & (Y m)) & (Y (H (!((!m) "
       "& (Y m))))))) S p) & (O[0,3] p)) <-> r) & (((! m) & (Y m)) & (Y (H (! ((! m) & (Y "
       "m)))))))))"},
      {"before m the sw shall always satisfy occurred(3, p) <-> r",
       "((H ((((m & ((! (Y TRUE)) | (Y (! m)))) & ((Y (H (! m))) | (! (Y TRUE)))) & (Y TRUE)) "
       "-> (Y (H ((((! (!(Y TRUE))) S p) & (O[0,3] p)) <-> r))))) & ((H (! ((m & ((! (Y TRUE)) "
       "| (Y (! m)))) & ((Y (H (! m))) | (! (Y TRUE)))))) -> (H ((((! (!(Y TRUE))) S p) & "
       "(O[0,3] p)) <-> r))))"},
  };
  const auto resolve_mpr = [](const std::string& name) -> monitor::Resolved {
    static const std::vector<std::string> names = {"m", "p", "r"};
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == name) return {monitor::Resolved::Kind::variable, static_cast<int>(i)};
    return {};
  };
  std::mt19937 rng(42);
  std::uniform_int_distribution<std::size_t> length(1, 24);
  for (const Case& c : cases) {
    const fretish::ParseResult parsed = parse_lowered("X: " + c.sentence + "\n");
    ASSERT_EQ(parsed.requirements.size(), 1u) << c.sentence;
    const PtFormula oracle = PtFormula::parse(c.formula);
    for (int k = 0; k < 200; ++k) {
      const auto trace = random_boolean_trace(rng, {"m", "p", "r"}, length(rng));
      const std::vector<bool> expected = oracle.evaluate(trace);
      std::string reason;
      auto run = monitor::RequirementMonitor::compile(parsed.requirements[0], resolve_mpr, reason);
      ASSERT_NE(run, nullptr) << c.sentence << ": " << reason;
      for (std::size_t t = 0; t < trace.size(); ++t) {
        std::vector<monitor::Val> frame;
        for (const char* n : {"m", "p", "r"})
          frame.push_back(monitor::Val::of_bool(trace[t].at(n).truth));
        const bool got = run->step(frame);
        ASSERT_FALSE(run->failed()) << run->error();
        ASSERT_EQ(got, expected[t]) << c.sentence << " at tick " << t << "\n" << trace_text(trace);
      }
    }
  }
}

TEST(MonitorClassify, WhatHasNoMeaningOnATraceIsNamed) {
  const auto reason_for = [](const std::string& sentence, std::optional<double> tick = {}) {
    const fretish::ParseResult parsed = parse_lowered("X: " + sentence + "\n", tick);
    EXPECT_EQ(parsed.requirements.size(), 1u) << sentence;
    if (parsed.requirements.empty()) return std::string();
    return monitor::classify(parsed.requirements[0]).reason;
  };
  EXPECT_EQ(reason_for("the sw shall with probability > 0.9 always satisfy p"),
            "probability 'with probability > 0.9': a run has no probability");
  EXPECT_EQ(reason_for("\"The rover is safe.\""),
            "freeform requirement: FRET does not formalize it");
  EXPECT_EQ(reason_for("the sw shall within 2 seconds satisfy p"),
            "timing 'within 2 seconds' is not in ticks and the domain declares no tick period "
            "(e.g. 'tick 100 ms' in domain.fret)");
  EXPECT_EQ(reason_for("the sw shall within 2 seconds satisfy p", 0.1), "");
  EXPECT_EQ(reason_for("the sw shall within 2.5 ticks satisfy p"),
            "timing 'within 2.5 ticks' is not a whole number of ticks");
}

// The lowering reports a duration it cannot convert once, at the duration; classify then gives
// the same reason, and the static checks do not report it again.
TEST(MonitorClassify, AnUnconvertedDurationIsOneErrorAtTheDuration) {
  for (const auto& [sentence, column, reason] :
       {std::tuple<std::string, int, std::string>{
            "the sw shall within 2 seconds satisfy p", 24,
            "timing 'within 2 seconds' is not in ticks and the domain declares no tick period "
            "(e.g. 'tick 100 ms' in domain.fret)"},
        {"upon c the sw shall for 2.5 ticks satisfy p", 28,
         "timing 'for 2.5 ticks' is not a whole number of ticks"},
        {"the sw shall after 10000000000000 ticks satisfy p", 23,
         "timing 'after 10000000000000 ticks' is out of range"}}) {
    const fretish::ParseResult parsed = parse_lowered("X: " + sentence + "\n");
    ASSERT_EQ(parsed.requirements.size(), 1u) << sentence;
    ASSERT_EQ(parsed.findings.size(), 1u) << sentence;
    const Finding& f = parsed.findings[0];
    EXPECT_EQ(f.check, "property-timing") << sentence;
    EXPECT_EQ(f.message, "X: " + reason) << sentence;
    EXPECT_EQ(f.location.file, "r.fret");
    EXPECT_EQ(f.location.line, 1);
    EXPECT_EQ(f.location.column, column) << sentence;
    EXPECT_EQ(monitor::classify(parsed.requirements[0]).reason, reason) << sentence;
    monitor::Observables observables;
    observables.variables = {{"c", monitor::Observables::Type::boolean},
                             {"p", monitor::Observables::Type::boolean}};
    EXPECT_TRUE(monitor::check_properties(parsed.requirements, observables).empty()) << sentence;
  }
}

TEST(MonitorClassify, DurationsInOtherUnitsRoundUpToTicks) {
  const auto ticks = [](const std::string& timing, double period) {
    const fretish::ParseResult parsed =
        parse_lowered("X: the sw shall " + timing + " satisfy p\n", period);
    EXPECT_EQ(parsed.requirements.size(), 1u) << timing;
    if (parsed.requirements.empty()) return std::uint64_t{0};
    const auto c = monitor::classify(parsed.requirements[0]);
    EXPECT_TRUE(c.shape) << c.reason;
    return c.shape ? c.shape->duration : std::uint64_t{0};
  };
  EXPECT_EQ(ticks("within 2 seconds", 0.1), 20u);
  EXPECT_EQ(ticks("within 250 milliseconds", 0.1), 3u);
  EXPECT_EQ(ticks("for 300 millisecs", 0.1), 3u);
  EXPECT_EQ(ticks("after 1 minute", 2.0), 30u);
  EXPECT_EQ(ticks("within 7 ticks", 0.1), 7u);
}

}  // namespace
}  // namespace uabt::testing
