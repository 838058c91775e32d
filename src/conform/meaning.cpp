// Conformance by meaning: a symbolic one-tick evaluation of a selection subtree (BT.CPP 4.10
// semantics from IDLE) against the requirements' "first enabled guard selects".
#include "conform/meaning.hpp"

#include <set>

#include "bt/node_kinds.hpp"
#include "bt/structure.hpp"
#include "conform/compare.hpp"
#include "conform/readback.hpp"
#include "smt/assign.hpp"
#include "smt/evaluate.hpp"

namespace uabt::conform {

namespace {

class TickReader {
 public:
  TickReader(const Context& ctx, const std::string& adaptable,
             const std::map<std::string, int>& codes)
      : ctx_(ctx), adaptable_(adaptable), codes_(codes) {}

  std::optional<TickNode> read(const bt::Node& n, const std::string& path, bool visible,
                               int depth) {
    if (depth > bt::kMaxDepth) return fail("nesting deeper than BT.CPP allows at " + path);
    const std::string kind = n.kind();
    TickNode t;
    t.node = &n;
    t.path = path;
    if (bt::is_subtree(kind)) return call(n, path, visible, depth);
    auto control = [&](TickNode::Op op, std::size_t min,
                       std::size_t max) -> std::optional<TickNode> {
      if (auto extra = extra_attribute(n))
        return fail("<" + kind + "> at " + path + " has " + *extra);
      if (n.children.size() < min || n.children.size() > max)
        return fail("<" + kind + "> at " + path + " has " + std::to_string(n.children.size()) +
                    " children");
      t.op = op;
      for (std::size_t i = 0; i < n.children.size(); ++i) {
        auto c = read(n.children[i], child_path(path, n.children[i], i), visible, depth + 1);
        if (!c) return std::nullopt;
        t.children.push_back(std::move(*c));
      }
      return t;
    };
    using K = bt::NodeKind;
    using Op = TickNode::Op;
    static const std::map<K, Op> kOps = {{K::sequence, Op::sequence},
                                         {K::reactive_sequence, Op::sequence},
                                         {K::sequence_with_memory, Op::sequence},
                                         {K::fallback, Op::fallback},
                                         {K::reactive_fallback, Op::fallback},
                                         {K::if_then_else, Op::if_then_else},
                                         {K::while_do_else, Op::if_then_else},
                                         {K::inverter, Op::invert},
                                         {K::force_success, Op::force_success},
                                         {K::force_failure, Op::force_failure}};
    const K k = bt::node_kind(kind);
    if (const auto op = kOps.find(k); op != kOps.end()) {
      const bt::BuiltinNode& b = bt::builtin(k);
      return control(op->second, static_cast<std::size_t>(b.min_children),
                     b.max_children < 0 ? SIZE_MAX : static_cast<std::size_t>(b.max_children));
    }
    GuardReading g = read_guard(ctx_, n, path, visible);
    if (g.problem) return fail(g.problem->message + " (at " + g.problem->path + ")");
    t.op = TickNode::Op::condition;
    t.condition = g.formula;
    return t;
  }

  const std::string& problem() const { return problem_; }
  std::vector<SelectionMeaning::Call>& calls() { return calls_; }

 private:
  std::optional<TickNode> fail(std::string why) {
    if (problem_.empty()) problem_ = std::move(why);
    return std::nullopt;
  }

  std::optional<TickNode> call(const bt::Node& n, const std::string& path, bool visible,
                               int depth) {
    const int format = ctx_.compiled().format;
    if (const auto remaps = remapping_attributes(n, format); !remaps.empty())
      return fail("the call at " + path + " has " + remaps.front() +
                  ": it does not pass the parent's blackboard unchanged");
    const std::string* id = n.attribute("ID");
    const bt::TreeDef* target = id ? ctx_.compiled().find_tree(*id) : nullptr;
    if (target == nullptr || target->root.tag.empty())
      return fail("the call at " + path + " names no tree");
    const std::vector<std::string> alts = ctx_.alternatives_called(adaptable_, *id);
    if (!alts.empty()) {
      const std::string& alt = alts.front();
      TickNode t;
      t.op = TickNode::Op::alternative;
      t.alternative = codes_.at(alt);
      t.node = &n;
      t.path = path;
      calls_.push_back({alt, &n, path});
      return t;
    }
    if (!calling_.insert(target->id).second) return fail("SubTree cycle through " + target->id);
    auto r =
        read(target->root, root_path(*target), visible && shares_blackboard(n, format), depth + 1);
    calling_.erase(target->id);
    return r;
  }

  const Context& ctx_;
  const std::string& adaptable_;
  const std::map<std::string, int>& codes_;
  std::string problem_;
  std::vector<SelectionMeaning::Call> calls_;
  std::set<std::string> calling_;
};

// The outcome code of one tick, over Z3 (symbolic) or over a state (concrete).
class Symbolic {
 public:
  explicit Symbolic(Prover& prover) : prover_(prover), c_(prover.context()) {}

  std::optional<z3::expr> eval(const TickNode& t) {
    const z3::expr S = c_.int_val(kSelectsNothingButSucceeds), F = c_.int_val(kFails);
    switch (t.op) {
      case TickNode::Op::success: return S;
      case TickNode::Op::failure: return F;
      case TickNode::Op::alternative: return c_.int_val(t.alternative);
      case TickNode::Op::condition: {
        auto b = prover_.lower(t.condition, error);
        if (!b) return std::nullopt;
        return z3::ite(*b, S, F);
      }
      case TickNode::Op::sequence:
      case TickNode::Op::fallback: {
        // Sequence: go on while children succeed; Fallback: while they fail.
        const z3::expr& go_on = t.op == TickNode::Op::sequence ? S : F;
        auto rest = eval(t.children.back());
        if (!rest) return std::nullopt;
        for (std::size_t i = t.children.size() - 1; i-- > 0;) {
          auto o = eval(t.children[i]);
          if (!o) return std::nullopt;
          rest = z3::ite(*o == go_on, *rest, *o);
        }
        return rest;
      }
      case TickNode::Op::invert: {
        auto o = eval(t.children[0]);
        if (!o) return std::nullopt;
        return z3::ite(*o == S, F, z3::ite(*o == F, S, *o));
      }
      case TickNode::Op::force_success:
      case TickNode::Op::force_failure: {
        auto o = eval(t.children[0]);
        if (!o) return std::nullopt;
        return z3::ite(*o < 0, t.op == TickNode::Op::force_success ? S : F, *o);
      }
      case TickNode::Op::if_then_else: {
        auto cond = eval(t.children[0]);
        auto then = eval(t.children[1]);
        auto other = t.children.size() > 2 ? eval(t.children[2]) : std::optional<z3::expr>(F);
        if (!cond || !then || !other) return std::nullopt;
        return z3::ite(*cond == S, *then, z3::ite(*cond == F, *other, *cond));
      }
    }
    return std::nullopt;
  }

  std::string error;

 private:
  Prover& prover_;
  z3::context& c_;
};

std::optional<int> concrete(const TickNode& t, const fretish::Domain& d, const State& s) {
  auto child = [&](std::size_t i) { return concrete(t.children[i], d, s); };
  switch (t.op) {
    case TickNode::Op::success: return kSelectsNothingButSucceeds;
    case TickNode::Op::failure: return kFails;
    case TickNode::Op::alternative: return t.alternative;
    case TickNode::Op::condition: {
      auto v = smt::try_evaluate(*t.condition, d, s);
      if (!v) return std::nullopt;
      return *v ? kSelectsNothingButSucceeds : kFails;
    }
    case TickNode::Op::sequence:
    case TickNode::Op::fallback: {
      const int go_on = t.op == TickNode::Op::sequence ? kSelectsNothingButSucceeds : kFails;
      std::optional<int> o;
      for (std::size_t i = 0; i < t.children.size(); ++i) {
        o = child(i);
        if (!o || *o != go_on) return o;
      }
      return o;
    }
    case TickNode::Op::invert: {
      auto o = child(0);
      if (!o || *o >= 0) return o;
      return *o == kFails ? kSelectsNothingButSucceeds : kFails;
    }
    case TickNode::Op::force_success:
    case TickNode::Op::force_failure: {
      auto o = child(0);
      if (!o || *o >= 0) return o;
      return t.op == TickNode::Op::force_success ? kSelectsNothingButSucceeds : kFails;
    }
    case TickNode::Op::if_then_else: {
      auto o = child(0);
      if (!o || *o >= 0) return o;
      if (*o == kSelectsNothingButSucceeds) return child(1);
      return t.children.size() > 2 ? child(2) : std::optional<int>(kFails);
    }
  }
  return std::nullopt;
}

}  // namespace

SelectionMeaning prove_selection_meaning(const Context& ctx, Prover& prover,
                                         const std::string& adaptable, const bt::TreeDef& tree) {
  SelectionMeaning out;
  const load::Mission& m = ctx.mission();
  std::map<std::string, int> codes;
  std::vector<std::string> names;
  auto code_of = [&](const std::string& alt) {
    if (codes.emplace(alt, static_cast<int>(names.size())).second) names.push_back(alt);
    return codes.at(alt);
  };
  for (const auto& alt : m.alternatives)
    if (alt.adaptable == adaptable) code_of(alt.name);
  const auto reqs = m.selections_for(adaptable);
  for (const auto* r : reqs) code_of(r->alternative);

  TickReader reader(ctx, adaptable, codes);
  auto tick = reader.read(tree.root, root_path(tree), true, 1);
  out.calls = std::move(reader.calls());
  if (!tick) {
    out.reason = reader.problem();
    return out;
  }
  Symbolic symbolic(prover);
  auto compiled = symbolic.eval(*tick);
  if (!compiled) {
    out.reason = "a condition does not type check against the domain: " + symbolic.error;
    return out;
  }
  z3::expr required = prover.context().int_val(kFails);
  for (auto it = reqs.rbegin(); it != reqs.rend(); ++it) {
    std::string error;
    auto g = (*it)->guard ? prover.lower((*it)->guard, error) : prover.truth(true);
    if (!g) {
      out.verdict = SelectionMeaning::Verdict::unknown;
      out.reason = "requirement " + (*it)->id + "'s guard does not type check: " + error;
      return out;
    }
    smt::assign(required,
                z3::ite(*g, prover.context().int_val(codes.at((*it)->alternative)), required));
  }
  const Proof proof = prover.equivalent(*compiled, required);
  if (proof.answer == Answer::holds) {
    out.verdict = SelectionMeaning::Verdict::equal;
    return out;
  }
  if (proof.answer == Answer::unknown) {
    out.verdict = SelectionMeaning::Verdict::unknown;
    out.reason = "the solver answered unknown (" + proof.reason + ")";
    return out;
  }
  out.verdict = SelectionMeaning::Verdict::differs;
  out.witness = proof.witness;
  auto describe_code = [&](std::optional<int> code) -> std::string {
    if (!code) return "?";
    if (*code == kFails) return "nothing (the selection fails)";
    if (*code == kSelectsNothingButSucceeds) return "nothing, yet succeeds";
    return names.at(static_cast<std::size_t>(*code));
  };
  const auto compiled_code = concrete(*tick, m.domain, proof.witness);
  out.compiled_selects = describe_code(compiled_code);
  if (compiled_code && *compiled_code >= 0)
    out.alternatives.push_back(names.at(static_cast<std::size_t>(*compiled_code)));
  out.required_selects = describe_code(kFails);
  for (const auto* r : reqs) {
    const auto v = r->guard ? smt::try_evaluate(*r->guard, m.domain, proof.witness) : true;
    if (!v) {
      out.required_selects = "?";
      break;
    }
    if (*v) {
      out.required_selects = r->alternative + " (" + r->id + ")";
      out.required_by = r->id;
      out.alternatives.push_back(r->alternative);
      break;
    }
  }
  return out;
}

}  // namespace uabt::conform
