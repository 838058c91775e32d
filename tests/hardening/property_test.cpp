// Property tests over random missions (fixed seeds, so every run checks the same missions):
//  (a) the compiled tree, written, read back and ticked by the runtime engine, selects exactly
//      "the first requirement whose guard holds" in every state;
//  (b) the verifier's verdicts (overlap, gap, unsatisfiable, shadowed) and its coverage counts
//      agree with brute-force enumeration of the small discrete domain.
// The oracle is independent of uabt: each random guard is generated as a small formula tree that
// this file evaluates itself; uabt only ever sees its FRETISH text. smt::evaluate is checked
// against the oracle too.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "bt/xml_io.hpp"
#include "compile/compile.hpp"
#include "hardening_support.hpp"
#include "runtime/engine.hpp"
#include "runtime/world.hpp"
#include "smt/evaluate.hpp"
#include "verify/verify.hpp"

namespace uabt::testing {
namespace {

// --- the state space: b0, b1, b2 booleans, gear in {m0, m1, m2}, lvl in [0, 4] -----------------

constexpr int kBooleans = 3;
constexpr int kModes = 3;
constexpr int kLevels = 5;

struct S {
  bool b[kBooleans] = {};
  int mode = 0;
  int lvl = 0;
};

std::vector<S> all_states() {
  std::vector<S> out;
  for (int bits = 0; bits < (1 << kBooleans); ++bits)
    for (int mode = 0; mode < kModes; ++mode)
      for (int lvl = 0; lvl < kLevels; ++lvl) {
        S s;
        for (int k = 0; k < kBooleans; ++k) s.b[k] = (bits >> k) & 1;
        s.mode = mode;
        s.lvl = lvl;
        out.push_back(s);
      }
  return out;
}

const char* kDomain =
    "boolean b0, b1, b2\n"
    "enum gear in {m0, m1, m2}\n"
    "integer lvl in [0, 4]\n";

State to_state(const S& s) {
  State out;
  for (int k = 0; k < kBooleans; ++k)
    out.emplace_back("b" + std::to_string(k), Value::of_bool(s.b[k]));
  out.emplace_back("gear", Value::of_enum("m" + std::to_string(s.mode)));
  out.emplace_back("lvl", Value::of_int(s.lvl));
  return out;
}

// --- random formulas with their own meaning -----------------------------------------------

struct Atom {
  std::string text;
  std::function<bool(const S&)> holds;
  std::set<std::string> vars;
};

// A deterministic generator: std::mt19937's output is fixed by the standard, and the
// distributions below are written out so that every library gives the same missions.
class Random {
 public:
  explicit Random(std::uint32_t seed) : engine_(seed) {}
  int below(int n) { return static_cast<int>(engine_() % static_cast<std::uint32_t>(n)); }
  bool chance(int percent) { return below(100) < percent; }

 private:
  std::mt19937 engine_;
};

Atom random_atom(Random& r) {
  const int k = r.below(kLevels);
  const int m = r.below(kModes);
  const std::string ks = std::to_string(k), ms = "m" + std::to_string(m);
  switch (r.below(12)) {
    case 0:
    case 1:
    case 2: {
      const int b = r.below(kBooleans);
      return {
          "b" + std::to_string(b), [b](const S& s) { return s.b[b]; }, {"b" + std::to_string(b)}};
    }
    case 3: return {"gear = " + ms, [m](const S& s) { return s.mode == m; }, {"gear"}};
    case 4: return {"gear != " + ms, [m](const S& s) { return s.mode != m; }, {"gear"}};
    case 5: return {ms + " = gear", [m](const S& s) { return s.mode == m; }, {"gear"}};
    case 6: return {"lvl < " + ks, [k](const S& s) { return s.lvl < k; }, {"lvl"}};
    case 7: return {"lvl >= " + ks, [k](const S& s) { return s.lvl >= k; }, {"lvl"}};
    case 8: return {"lvl = " + ks, [k](const S& s) { return s.lvl == k; }, {"lvl"}};
    case 9: return {"lvl + 1 > " + ks, [k](const S& s) { return s.lvl + 1 > k; }, {"lvl"}};
    case 10: return {"2 * lvl <= " + ks, [k](const S& s) { return 2 * s.lvl <= k; }, {"lvl"}};
    default: return {"-1 < lvl - " + ks, [k](const S& s) { return -1 < s.lvl - k; }, {"lvl"}};
  }
}

struct Formula {
  std::string text;  // fully parenthesized FRETISH
  std::function<bool(const S&)> holds;
};

Formula random_formula(Random& r, int depth) {
  if (depth == 0 || r.chance(35)) {
    Atom a = random_atom(r);
    return {a.text, a.holds};
  }
  if (r.chance(15)) {
    Formula f = random_formula(r, depth - 1);
    auto h = f.holds;
    return {"!(" + f.text + ")", [h](const S& s) { return !h(s); }};
  }
  Formula a = random_formula(r, depth - 1), b = random_formula(r, depth - 1);
  auto ha = a.holds, hb = b.holds;
  switch (r.below(6)) {
    case 0:
    case 1:
      return {"(" + a.text + " & " + b.text + ")", [ha, hb](const S& s) { return ha(s) && hb(s); }};
    case 2:
    case 3:
      return {"(" + a.text + " | " + b.text + ")", [ha, hb](const S& s) { return ha(s) || hb(s); }};
    case 4:
      return {"(" + a.text + " xor " + b.text + ")",
              [ha, hb](const S& s) { return ha(s) != hb(s); }};
    default:
      return {"(" + a.text + " -> " + b.text + ")",
              [ha, hb](const S& s) { return !ha(s) || hb(s); }};
  }
}

// --- random missions ---------------------------------------------------------------------------

struct Req {
  std::string id;
  std::string alternative;
  std::optional<Formula> guard;  // nullopt: the default
};

struct RandomMission {
  std::vector<Req> requirements;  // file order
  std::vector<Formula> assumptions;
  std::map<std::string, std::string> files;
  bool reactive = false;

  // Priority order: the guarded requirements in file order, then the default.
  std::vector<const Req*> priority() const {
    std::vector<const Req*> out;
    for (const Req& r : requirements)
      if (r.guard) out.push_back(&r);
    for (const Req& r : requirements)
      if (!r.guard) out.push_back(&r);
    return out;
  }
  bool in_domain(const S& s) const {
    return std::all_of(assumptions.begin(), assumptions.end(),
                       [&](const Formula& a) { return a.holds(s); });
  }
  // The oracle: the requirement the paper's Fallback selects, or nullptr.
  const Req* selected(const S& s) const {
    for (const Req* r : priority())
      if (!r->guard || r->guard->holds(s)) return r;
    return nullptr;
  }
};

std::string alternative_xml(const std::string& alt) {
  return alternative_tree(alt, "<Sequence>\n      <Run_" + alt + "/>\n    </Sequence>");
}

RandomMission random_mission(Random& r) {
  RandomMission m;
  const int guarded = 1 + r.below(5);
  const bool with_default = r.chance(50);
  const int default_at = with_default ? r.below(guarded + 1) : -1;
  std::string text = "# a random mission\n";
  int index = 0;
  for (int i = 0; i <= guarded; ++i) {
    if (i == default_at) {
      Req d{"Default", "dflt", std::nullopt};
      text += d.id + ": In nav Mission shall satisfy selected_alt = " + d.alternative + "\n";
      m.requirements.push_back(d);
    }
    if (i == guarded) break;
    Req q{"Q" + std::to_string(index), "alt" + std::to_string(index), random_formula(r, 3)};
    ++index;
    // The guard is written in one of FRETISH's condition forms; all mean the formula.
    std::string condition;
    switch (r.below(4)) {
      case 0: condition = "if " + q.guard->text; break;
      case 1: condition = "when " + q.guard->text; break;
      case 2: condition = "unless !(" + q.guard->text + ")"; break;
      default: condition = "upon " + q.guard->text + " is true"; break;
    }
    text += q.id + ": In nav " + condition +
            " Mission shall satisfy selected_alt = " + q.alternative + "\n";
    m.requirements.push_back(q);
  }
  std::string domain = kDomain;
  if (r.chance(40)) {
    m.assumptions.push_back({"!(b0 & b1)", [](const S& s) { return !(s.b[0] && s.b[1]); }});
    domain += "assume a0: !(b0 & b1)\n";
  }
  if (r.chance(25)) {
    m.assumptions.push_back({"b2 -> gear = m0", [](const S& s) { return !s.b[2] || s.mode == 0; }});
    domain += "assume a1: b2 -> gear = m0\n";
  }
  m.reactive = r.chance(30);
  m.files["mission.xml"] =
      mission_with("    <Sequence>\n      <Adaptable ID=\"nav\"/>\n      <Stop/>\n    </Sequence>");
  m.files["requirements.fret"] = text;
  m.files["domain.fret"] = domain;
  for (const Req& q : m.requirements)
    m.files["alternatives/nav/" + q.alternative + ".xml"] = alternative_xml(q.alternative);
  return m;
}

// --- the runtime world: conditions from the state, the alternatives' actions recorded ----------

class SelectionWorld : public runtime::World {
 public:
  S state;
  std::vector<std::string> ran;  // alternatives whose action was ticked

  std::uint32_t bind_leaf(const runtime::LeafBinding& leaf) override {
    kinds_.push_back(leaf.kind);
    return static_cast<std::uint32_t>(kinds_.size() - 1);
  }
  runtime::NodeStatus tick_leaf(const runtime::LeafContext& leaf) override {
    const std::string& kind = kinds_[leaf.handle];
    if (kind.starts_with("Run_")) {
      ran.push_back(kind.substr(4));
      return runtime::NodeStatus::success;
    }
    if (kind.size() == 2 && kind[0] == 'b' && kind[1] >= '0' && kind[1] < '0' + kBooleans)
      return state.b[kind[1] - '0'] ? runtime::NodeStatus::success : runtime::NodeStatus::failure;
    ADD_FAILURE() << "unexpected leaf " << kind;
    return runtime::NodeStatus::failure;
  }
  void halt_leaf(const runtime::LeafContext&) override {}

 private:
  std::vector<std::string> kinds_;
};

struct Loaded {
  std::unique_ptr<TempMission> dir;
  load::Mission mission;
};

Loaded load_random(const RandomMission& rm) {
  Loaded out;
  out.dir = std::make_unique<TempMission>(rm.files);
  std::string error;
  auto m = load::load_mission(out.dir->dir(), {}, error);
  if (!m) throw std::runtime_error("random mission did not load: " + error);
  out.mission = std::move(*m);
  return out;
}

constexpr std::uint32_t kSeed = 20240611;
constexpr int kMissions = 200;

// --- (a) compiled selection = first enabled requirement ----------------------------------------

TEST(Property, CompiledSelectionPicksTheFirstRequirementThatHolds) {
  Random r(kSeed);
  const std::vector<S> states = all_states();
  int checked_states = 0, failures = 0;
  for (int n = 0; n < kMissions && failures < 5; ++n) {
    const RandomMission rm = random_mission(r);
    SCOPED_TRACE("mission " + std::to_string(n) + ":\n" + rm.files.at("requirements.fret") +
                 rm.files.at("domain.fret"));
    Loaded loaded = load_random(rm);
    const load::Mission& m = loaded.mission;
    ASSERT_FALSE(has_errors(m.findings)) << format_text(m.findings);

    // The loader's reading of each guard means what the oracle means (smt::evaluate).
    for (const auto& s : m.selections) {
      const auto it = std::find_if(rm.requirements.begin(), rm.requirements.end(),
                                   [&](const Req& q) { return q.id == s.id; });
      ASSERT_NE(it, rm.requirements.end());
      ASSERT_EQ(s.guard == nullptr, !it->guard.has_value());
      if (!s.guard) continue;
      for (const S& st : states)
        ASSERT_EQ(smt::evaluate(*s.guard, m.domain, to_state(st)), it->guard->holds(st))
            << s.id << ": " << fretish::to_fretish(*s.guard);
    }

    compile::Options options;
    options.selection =
        rm.reactive ? compile::SelectionStyle::reactive : compile::SelectionStyle::sequence;
    const compile::Result compiled = compile::compile_mission(m, options);
    ASSERT_TRUE(compiled.ok) << format_text(compiled.findings);
    // Tick the bytes that would be uplinked, not the in-memory document.
    const std::string xml = bt::write_document(compiled.document);
    std::vector<Finding> read_findings;
    const auto doc = bt::parse_document(xml, "compiled.xml", read_findings);
    ASSERT_TRUE(doc.has_value()) << format_text(read_findings);

    SelectionWorld world;
    runtime::Engine engine = runtime::Engine::build(*doc, "nav", world);
    for (const S& st : states) {
      if (!rm.in_domain(st)) continue;
      world.state = st;
      world.ran.clear();
      runtime::Blackboard& bb = engine.blackboard();
      for (int k = 0; k < kBooleans; ++k)
        bb.set("b" + std::to_string(k), runtime::ScriptValue::of_bool(st.b[k]));
      bb.set("gear", runtime::ScriptValue::of_string("m" + std::to_string(st.mode)));
      bb.set("lvl", runtime::ScriptValue::of_int(st.lvl));
      const runtime::NodeStatus status = engine.tick();
      const Req* expected = rm.selected(st);
      const std::vector<std::string> want =
          expected ? std::vector<std::string>{expected->alternative} : std::vector<std::string>{};
      if (world.ran != want ||
          status != (expected ? runtime::NodeStatus::success : runtime::NodeStatus::failure)) {
        ++failures;
        ADD_FAILURE() << "state " << format_state(to_state(st)) << ": expected "
                      << (expected ? expected->alternative : "none (FAILURE)") << ", ran "
                      << (world.ran.empty() ? "nothing" : world.ran.front()) << " with status "
                      << runtime::status_name(status) << "\n"
                      << xml;
        break;
      }
      ++checked_states;
    }
    ASSERT_TRUE(engine.errors().empty()) << engine.errors().front().message;
  }
  EXPECT_GT(checked_states, kMissions * 20);
}

// --- (b) the verifier agrees with brute force ------------------------------------------------

TEST(Property, VerdictsAndCoverageAgreeWithBruteForce) {
  Random r(kSeed + 1);
  const std::vector<S> states = all_states();
  int overlaps = 0, gaps = 0, unsatisfiable = 0, shadowed = 0;
  for (int n = 0; n < kMissions; ++n) {
    const RandomMission rm = random_mission(r);
    SCOPED_TRACE("mission " + std::to_string(n) + ":\n" + rm.files.at("requirements.fret") +
                 rm.files.at("domain.fret"));
    Loaded loaded = load_random(rm);
    const load::Mission& m = loaded.mission;
    ASSERT_FALSE(has_errors(m.findings)) << format_text(m.findings);
    verify::Options options;
    options.timeout_ms = 20000;
    options.threads = 1;
    const verify::Result result = verify::verify_mission(m, options);

    std::vector<S> domain;
    for (const S& st : states)
      if (rm.in_domain(st)) domain.push_back(st);
    ASSERT_FALSE(domain.empty());
    const std::vector<const Req*> order = rm.priority();

    auto has = [&](const std::string& check, std::vector<std::string> reqs) {
      return std::any_of(result.findings.begin(), result.findings.end(), [&](const Finding& f) {
        if (f.check != check) return false;
        if (reqs.empty()) return true;
        return f.requirements.size() >= reqs.size() &&
               std::equal(reqs.begin(), reqs.end(), f.requirements.begin());
      });
    };
    for (const Finding& f : result.findings) {
      ASSERT_NE(f.check, "verification-inconclusive") << f.message;
      ASSERT_NE(f.check, "domain-inconsistent") << f.message;
      if (f.check == "guard-overlap" || f.check == "guard-gap" || f.check == "guard-shadowed") {
        // The witness is a state of the domain in which the finding holds.
        ASSERT_TRUE(smt::satisfies_domain(m.domain, f.witness)) << format_state(f.witness);
      }
    }

    // Overlap: some state of D satisfies two guards (defaults excluded).
    for (std::size_t i = 0; i < order.size(); ++i) {
      for (std::size_t j = i + 1; j < order.size(); ++j) {
        if (!order[i]->guard || !order[j]->guard) continue;
        const bool both = std::any_of(domain.begin(), domain.end(), [&](const S& st) {
          return order[i]->guard->holds(st) && order[j]->guard->holds(st);
        });
        EXPECT_EQ(has("guard-overlap", {order[i]->id, order[j]->id}), both)
            << order[i]->id << " / " << order[j]->id;
        overlaps += both;
      }
    }
    // Gap: without a default, some state of D satisfies no guard.
    const bool gap = std::any_of(domain.begin(), domain.end(),
                                 [&](const S& st) { return rm.selected(st) == nullptr; });
    EXPECT_EQ(has("guard-gap", {}), gap);
    gaps += gap;
    // Unsatisfiable and shadowed guards.
    for (std::size_t i = 0; i < order.size(); ++i) {
      if (!order[i]->guard) continue;
      const bool sat = std::any_of(domain.begin(), domain.end(),
                                   [&](const S& st) { return order[i]->guard->holds(st); });
      const bool selected = std::any_of(domain.begin(), domain.end(),
                                        [&](const S& st) { return rm.selected(st) == order[i]; });
      EXPECT_EQ(has("guard-unsatisfiable", {order[i]->id}), !sat) << order[i]->id;
      EXPECT_EQ(has("guard-shadowed", {order[i]->id}), sat && !selected) << order[i]->id;
      unsatisfiable += !sat;
      shadowed += sat && !selected;
    }

    // Coverage, counted over the variables the guards (and the assumptions linked to them)
    // range over: project each state of D onto them.
    ASSERT_EQ(result.coverage.size(), 1u);
    const verify::Coverage& cov = result.coverage[0];
    ASSERT_TRUE(cov.counted) << cov.not_counted_reason;
    auto project = [&](const S& st) {
      std::string key;
      for (const std::string& v : cov.variables)
        key += v + "=" + find_value(to_state(st), v)->to_string() + ";";
      return key;
    };
    std::map<std::string, S> projected;
    for (const S& st : domain) projected.emplace(project(st), st);
    EXPECT_EQ(cov.states, projected.size());
    std::uint64_t gap_states = 0, overlap_states = 0;
    std::vector<std::uint64_t> selected(order.size(), 0), enabled(order.size(), 0);
    for (const auto& [key, st] : projected) {
      const Req* pick = rm.selected(st);
      gap_states += pick == nullptr;
      int holding = 0;
      for (std::size_t k = 0; k < order.size(); ++k) {
        const bool on = !order[k]->guard || order[k]->guard->holds(st);
        enabled[k] += on;
        selected[k] += pick == order[k];
        holding += on && order[k]->guard.has_value();
      }
      overlap_states += holding >= 2;
    }
    EXPECT_EQ(cov.gap_states, gap_states);
    EXPECT_EQ(cov.overlap_states, overlap_states);
    ASSERT_EQ(cov.alternatives.size(), order.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
      EXPECT_EQ(cov.alternatives[k].requirement, order[k]->id);
      EXPECT_EQ(cov.alternatives[k].states, selected[k]) << order[k]->id;
      EXPECT_EQ(cov.alternatives[k].enabled_states, enabled[k]) << order[k]->id;
      EXPECT_EQ(cov.alternatives[k].reachable, selected[k] > 0) << order[k]->id;
    }
    if (::testing::Test::HasFailure()) break;
  }
  // The random missions exercise every verdict, both ways.
  EXPECT_GT(overlaps, 20);
  EXPECT_GT(gaps, 20);
  EXPECT_GT(unsatisfiable, 0);
  EXPECT_GT(shadowed, 5);
}

}  // namespace
}  // namespace uabt::testing
