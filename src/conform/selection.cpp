// One adaptable node's selection tree against its requirements.
#include "conform/selection.hpp"

#include <algorithm>
#include <map>

#include "bt/node_kinds.hpp"
#include "conform/compare.hpp"
#include "conform/meaning.hpp"
#include "conform/readback.hpp"
#include "conform/selector_shape.hpp"
#include "smt/assign.hpp"
#include "smt/evaluate.hpp"

namespace uabt::conform {

namespace {

struct RequirementSlot {
  const fretish::SelectionRequirement* source = nullptr;
  std::optional<z3::expr> guard;  // lowered; `true` for the default
  std::string text;               // FRETISH text of the guard
  std::string error;              // why it could not be lowered
  std::optional<std::size_t> branch;
};

struct BranchSlot {
  Branch shape;
  fretish::ExprPtr formula;         // what its condition-checking subtree decides
  std::optional<z3::expr> meaning;  // lowered; unset when unreadable or ill-typed
  std::optional<std::size_t> requirement;

  bool runs(const std::string& alternative) const {
    return std::find(shape.alternatives.begin(), shape.alternatives.end(), alternative) !=
           shape.alternatives.end();
  }
};

std::string guard_text(const fretish::SelectionRequirement& r) {
  return r.guard ? fretish::to_fretish(*r.guard) : "true (the default: no condition)";
}

// The trees an alternative brings: its main tree and the trees it calls, in its own file.
std::vector<const bt::TreeDef*> reachable_trees(const load::Alternative& alt) {
  std::vector<const bt::TreeDef*> out;
  const bt::TreeDef* main = alt.document.find_tree(alt.tree_id);
  if (main == nullptr) return out;
  std::vector<const bt::TreeDef*> pending{main};
  std::set<std::string> seen{main->id};
  while (!pending.empty()) {
    const bt::TreeDef* t = pending.back();
    pending.pop_back();
    out.push_back(t);
    std::vector<const bt::Node*> nodes{&t->root};
    while (!nodes.empty()) {
      const bt::Node* n = nodes.back();
      nodes.pop_back();
      const std::string* id = n->attribute("ID");
      if (bt::is_subtree(n->kind()) && id)
        if (const bt::TreeDef* called = alt.document.find_tree(*id))
          if (seen.insert(called->id).second) pending.push_back(called);
      for (const auto& c : n->children) nodes.push_back(&c);
    }
  }
  return out;
}

// compiled-alternative-mismatch: the trees alternative `name` runs through `call` must equal
// its source file's; once per alternative.
void check_alternative_trees(Context& ctx, const std::string& adaptable, const std::string& name,
                             const bt::Node* call, std::set<std::string>& checked) {
  if (!checked.insert(adaptable + "/" + name).second) return;
  const load::Alternative* alt = ctx.mission().find_alternative(adaptable, name);
  if (alt == nullptr) return;
  for (const bt::TreeDef* source : reachable_trees(*alt)) {
    const bool is_main = source->id == alt->tree_id;
    // A main tree matched by content may carry another ID; its call names it.
    const std::string* call_id = call ? call->attribute("ID") : nullptr;
    const std::string id = is_main && call_id ? *call_id : source->id;
    const bt::TreeDef* compiled = ctx.compiled().find_tree(id);
    // A missing tree is a SubTree call that dangles: compiled-dangling-subtree says so.
    if (compiled == nullptr) continue;
    auto diff = first_difference(source->root, compiled->root, root_path(*compiled), nullptr);
    if (!diff) continue;
    Finding& f = ctx.report("compiled-alternative-mismatch",
                            "tree '" + compiled->id + "' differs from alternative " + name + " (" +
                                alt->file + ") at " + diff->path + ": " + diff->what,
                            *diff->node, diff->path);
    f.adaptable = adaptable;
    f.alternatives = {name};
    break;  // the first difference of the alternative
  }
}

class SelectionCheck {
 public:
  SelectionCheck(Context& ctx, Prover& prover, std::string adaptable, Selector selector,
                 std::set<std::string>& checked_alternatives)
      : ctx_(ctx),
        prover_(prover),
        adaptable_(std::move(adaptable)),
        selector_(std::move(selector)),
        checked_alternatives_(checked_alternatives) {}

  void run() {
    lower_requirements();
    read_guards();
    match_equivalent();
    match_remaining();
    report_unmatched();
    check_order();
    check_alternatives();
  }

 private:
  Finding& report(const std::string& check, std::string message, const bt::Node& node,
                  const std::string& path) {
    Finding& f = ctx_.report(check, std::move(message), node, path);
    f.adaptable = adaptable_;
    return f;
  }

  std::string branch_label(std::size_t b) const {
    const Branch& s = selector_.branches[b];
    std::string label = "branch " + std::to_string(b) + " of '" + adaptable_ + "'";
    if (!s.alternatives.empty()) label += " (runs " + s.alternatives.front() + ")";
    return label;
  }

  void lower_requirements() {
    for (const auto* r : ctx_.mission().selections_for(adaptable_)) {
      RequirementSlot slot;
      slot.source = r;
      slot.text = guard_text(*r);
      if (r->guard)
        slot.guard = prover_.lower(r->guard, slot.error);
      else
        slot.guard = prover_.truth(true);
      requirements_.push_back(std::move(slot));
    }
  }

  void read_guards() {
    for (const Branch& shape : selector_.branches) {
      BranchSlot slot;
      slot.shape = shape;
      if (!shape.well_formed) {
        branches_.push_back(std::move(slot));
        continue;
      }
      if (shape.guard == nullptr) {
        slot.formula = fretish::make_bool(true);
      } else {
        GuardReading reading =
            read_guard(ctx_, *shape.guard, shape.guard_path, selector_.blackboard_visible);
        if (reading.problem) {
          const GuardProblem& p = *reading.problem;
          if (!p.reported_elsewhere)
            report("compiled-guard-mismatch",
                   "the condition-checking subtree of " + branch_label(shape.index) +
                       " is not a condition: " + p.message,
                   *p.node, p.path);
          branches_.push_back(std::move(slot));
          continue;
        }
        slot.formula = reading.formula;
      }
      std::string error;
      slot.meaning = prover_.lower(slot.formula, error);
      if (!slot.meaning)
        report("compiled-guard-mismatch",
               "the condition-checking subtree of " + branch_label(shape.index) + " reads as '" +
                   fretish::to_fretish(*slot.formula) +
                   "', which does not type check against the domain: " + error,
               shape.guard ? *shape.guard : *shape.node,
               shape.guard ? shape.guard_path : shape.path);
      branches_.push_back(std::move(slot));
    }
  }

  Proof compare(std::size_t r, std::size_t b) {
    const auto key = std::make_pair(r, b);
    auto it = proofs_.find(key);
    if (it == proofs_.end())
      it = proofs_.emplace(key, prover_.equivalent(*requirements_[r].guard, *branches_[b].meaning))
               .first;
    return it->second;
  }

  // Candidate branches for requirement r: unmatched, running its alternative; the branch that
  // carries the requirement's id as its name first (uabt names branches that way).
  std::vector<std::size_t> candidates(std::size_t r) const {
    const auto& req = *requirements_[r].source;
    std::vector<std::size_t> named, others;
    for (std::size_t b = 0; b < branches_.size(); ++b) {
      const BranchSlot& slot = branches_[b];
      if (slot.requirement || !slot.runs(req.alternative)) continue;
      (slot.shape.name == req.id ? named : others).push_back(b);
    }
    named.insert(named.end(), others.begin(), others.end());
    return named;
  }

  void bind(std::size_t r, std::size_t b) {
    requirements_[r].branch = b;
    branches_[b].requirement = r;
  }

  // First the pairs that agree: a requirement takes a branch running its alternative whose
  // guard is equivalent to its own.
  void match_equivalent() {
    for (std::size_t r = 0; r < requirements_.size(); ++r) {
      if (!requirements_[r].guard) continue;
      for (std::size_t b : candidates(r)) {
        if (!branches_[b].meaning) continue;
        if (compare(r, b).answer == Answer::holds) {
          bind(r, b);
          break;
        }
      }
    }
  }

  // Then what is left pairs by alternative alone; those pairs' guards differ.
  void match_remaining() {
    for (std::size_t r = 0; r < requirements_.size(); ++r) {
      if (requirements_[r].branch) continue;
      const auto options = candidates(r);
      if (options.empty()) continue;
      const std::size_t b = options.front();
      bind(r, b);
      const RequirementSlot& req = requirements_[r];
      const BranchSlot& branch = branches_[b];
      if (!branch.meaning) continue;  // unreadable or misshapen: reported already
      const bt::Node& at = branch.shape.guard ? *branch.shape.guard : *branch.shape.node;
      const std::string& path = branch.shape.guard ? branch.shape.guard_path : branch.shape.path;
      if (!req.guard) {
        Finding& f = report("verification-inconclusive",
                            "requirement " + req.source->id + "'s guard '" + req.text +
                                "' does not type check (" + req.error + "), so " + branch_label(b) +
                                " cannot be compared with it",
                            at, path);
        f.requirements = {req.source->id};
        continue;
      }
      const Proof proof = compare(r, b);
      if (proof.answer == Answer::holds) continue;  // a candidate skipped by the first pass
      report_guard_difference(r, b, proof, at, path);
    }
  }

  void report_guard_difference(std::size_t r, std::size_t b, const Proof& proof, const bt::Node& at,
                               const std::string& path) {
    const RequirementSlot& req = requirements_[r];
    const BranchSlot& branch = branches_[b];
    const std::string compiled = branch.shape.guard
                                     ? "'" + fretish::to_fretish(*branch.formula) + "'"
                                     : "nothing (no condition-checking subtree: always true)";
    if (proof.answer == Answer::unknown) {
      Finding& f =
          report("verification-inconclusive",
                 "could not decide whether " + branch_label(b) + ", which checks " + compiled +
                     ", is equivalent to requirement " + req.source->id + "'s guard '" + req.text +
                     "': the solver answered unknown (" + proof.reason + ")",
                 at, path);
      f.requirements = {req.source->id};
      f.alternatives = {req.source->alternative};
      return;
    }
    std::string when;
    if (req.source->guard) {
      if (auto v = smt::try_evaluate(*req.source->guard, ctx_.mission().domain, proof.witness))
        when = *v ? " (the requirement's guard holds there, the branch's check fails)"
                  : " (the branch's check succeeds there, the requirement's guard does not hold)";
    } else {
      when = " (the branch's check fails there, but the default is always enabled)";
    }
    Finding& f =
        report("compiled-guard-mismatch",
               branch_label(b) + " checks " + compiled + ", which is not equivalent to " +
                   "requirement " + req.source->id + "'s guard '" + req.text +
                   "' under the domain; they differ in the state " + describe(proof.witness) + when,
               at, path);
    f.requirements = {req.source->id};
    f.alternatives = {req.source->alternative};
    f.witness = proof.witness;
  }

  void report_unmatched() {
    for (const RequirementSlot& req : requirements_) {
      if (req.branch) continue;
      std::string why;
      for (const BranchSlot& b : branches_)
        if (b.runs(req.source->alternative) && b.requirement)
          why = "; branch " + std::to_string(b.shape.index) + " runs " + req.source->alternative +
                " for requirement " + requirements_[*b.requirement].source->id;
      Finding& f = report("compiled-missing-alternative",
                          "requirement " + req.source->id + " (if " + req.text +
                              " then selected_alt = " + req.source->alternative +
                              ") has no branch in the selection tree '" + adaptable_ + "'" + why,
                          selector_.tree->root, selector_.root_path);
      f.requirements = {req.source->id};
      f.alternatives = {req.source->alternative};
    }
    for (const BranchSlot& b : branches_) {
      if (b.requirement || b.shape.alternatives.empty()) continue;
      const std::string& alt = b.shape.alternatives.front();
      std::vector<std::string> owners;
      for (const RequirementSlot& req : requirements_)
        if (b.runs(req.source->alternative)) owners.push_back(req.source->id);
      const std::string message = owners.empty()
                                      ? branch_label(b.shape.index) + " runs " + alt +
                                            ", which no requirement of '" + adaptable_ + "' selects"
                                      : branch_label(b.shape.index) + " runs " + alt +
                                            " a second time: every requirement that selects it (" +
                                            owners.front() + (owners.size() > 1 ? ", …" : "") +
                                            ") already has its branch";
      Finding& f = report("compiled-missing-alternative", message, *b.shape.node, b.shape.path);
      f.alternatives = {alt};
    }
  }

  // The alternative the first enabled guard of `order` selects, as a Z3 integer (-1: none).
  z3::expr selection(const std::vector<std::size_t>& order) {
    std::map<std::string, int> codes;
    for (const RequirementSlot& r : requirements_)
      codes.emplace(r.source->alternative, static_cast<int>(codes.size()));
    z3::context& c = prover_.context();
    z3::expr chosen = c.int_val(-1);
    for (auto it = order.rbegin(); it != order.rend(); ++it)
      smt::assign(chosen,
                  z3::ite(*requirements_[*it].guard,
                          c.int_val(codes.at(requirements_[*it].source->alternative)), chosen));
    return chosen;
  }

  std::string selected_in(const std::vector<std::size_t>& order, const State& state) const {
    for (std::size_t r : order) {
      const auto* req = requirements_[r].source;
      const auto v =
          req->guard ? smt::try_evaluate(*req->guard, ctx_.mission().domain, state) : true;
      if (!v) return "?";
      if (*v) return req->alternative + " (" + req->id + ")";
    }
    return "nothing (the selector fails)";
  }

  void check_order() {
    std::vector<std::size_t> compiled;  // requirements in branch order
    for (const BranchSlot& b : branches_)
      if (b.requirement) compiled.push_back(*b.requirement);
    std::vector<std::size_t> required = compiled;
    std::sort(required.begin(), required.end());
    if (compiled == required) return;
    // The first branch that comes before a requirement of higher priority.
    std::size_t late = 0, early = 0;
    for (std::size_t i = 0; i + 1 < compiled.size(); ++i)
      if (compiled[i] > *std::min_element(compiled.begin() + i + 1, compiled.end())) {
        early = compiled[i];
        late = *std::min_element(compiled.begin() + i + 1, compiled.end());
        break;
      }
    auto ids = [&](const std::vector<std::size_t>& order) {
      std::string out;
      for (std::size_t r : order) out += (out.empty() ? "" : ", ") + requirements_[r].source->id;
      return out;
    };
    const RequirementSlot& first = requirements_[early];
    const RequirementSlot& second = requirements_[late];
    std::string message =
        "the branches of '" + adaptable_ + "' are not in priority order: branch " +
        std::to_string(*first.branch) + " (" + first.source->id + ") comes before branch " +
        std::to_string(*second.branch) + " (" + second.source->id + "); compiled order " +
        ids(compiled) + ", required order " + ids(required) + ". ";
    const bool all_lowered = std::all_of(compiled.begin(), compiled.end(), [&](std::size_t r) {
      return requirements_[r].guard.has_value();
    });
    State witness;
    if (!all_lowered) {
      message += "Whether this changes the selection was not decided: a guard does not type check";
    } else {
      const Proof proof = prover_.equivalent(selection(compiled), selection(required));
      if (proof.answer == Answer::holds) {
        message +=
            "No state of the domain selects differently (the reordered guards never overlap), "
            "but the tree no longer follows the requirement order";
      } else if (proof.answer == Answer::fails) {
        witness = proof.witness;
        message += "This changes the selection: in the state " + describe(witness) +
                   " the compiled tree selects " + selected_in(compiled, witness) +
                   " where the requirements select " + selected_in(required, witness);
      } else {
        message +=
            "Whether this changes the selection was not decided: the solver answered "
            "unknown (" +
            proof.reason + ")";
      }
    }
    const BranchSlot& at = branches_[*first.branch];
    Finding& f = report("compiled-order", message, *at.shape.node, at.shape.path);
    f.requirements = {second.source->id, first.source->id};  // priority order
    f.alternatives = {second.source->alternative, first.source->alternative};
    f.witness = witness;
  }

  void check_alternatives() {
    for (const BranchSlot& b : branches_) {
      if (b.shape.alternatives.empty()) continue;
      check_alternative_trees(ctx_, adaptable_, b.shape.alternatives.front(), b.shape.call,
                              checked_alternatives_);
    }
  }

  Context& ctx_;
  Prover& prover_;
  std::string adaptable_;
  Selector selector_;
  std::set<std::string>& checked_alternatives_;
  std::vector<RequirementSlot> requirements_;
  std::vector<BranchSlot> branches_;
  std::map<std::pair<std::size_t, std::size_t>, Proof> proofs_;
};

}  // namespace

namespace {

// A selection tree of another shape than Fig. 4: it conforms when its one-tick meaning equals
// the requirements' (ARCHITECTURE §6); the shape findings then only describe its style. When its
// meaning cannot be read, the shape findings stand and a Fig. 4-like tree gets the per-branch
// checks. Returns false in that case.
bool check_by_meaning(Context& ctx, Prover& prover, const std::string& adaptable,
                      std::vector<Finding>& shape_findings,
                      std::set<std::string>& checked_alternatives) {
  const bt::TreeDef* tree = ctx.compiled().find_tree(adaptable);
  if (tree == nullptr || tree->root.tag.empty()) return false;
  const SelectionMeaning meaning = prove_selection_meaning(ctx, prover, adaptable, *tree);
  const std::string path = root_path(*tree);
  switch (meaning.verdict) {
    case SelectionMeaning::Verdict::unreadable:
      for (Finding& f : shape_findings)
        f.notes.push_back("its meaning could not be read either: " + meaning.reason);
      return false;
    case SelectionMeaning::Verdict::unknown: {
      Finding& f = ctx.report("verification-inconclusive",
                              "could not decide whether the selection tree '" + adaptable +
                                  "' selects what the requirements select: " + meaning.reason,
                              tree->root, path);
      f.adaptable = adaptable;
      return false;
    }
    case SelectionMeaning::Verdict::equal:
    case SelectionMeaning::Verdict::differs: break;
  }
  for (Finding& f : shape_findings) {
    f.severity = Severity::note;
    f.notes.push_back(meaning.verdict == SelectionMeaning::Verdict::equal
                          ? "a matter of style: the selection is proved to select the same "
                            "alternative as the requirements in every state of the domain"
                          : "the selection's meaning was checked instead of its shape");
    ctx.findings().push_back(std::move(f));
  }
  if (meaning.verdict == SelectionMeaning::Verdict::equal) {
    for (const auto& call : meaning.calls)
      check_alternative_trees(ctx, adaptable, call.alternative, call.node, checked_alternatives);
    return true;
  }
  Finding& f =
      ctx.report("compiled-selection-mismatch",
                 "the selection tree '" + adaptable +
                     "' does not select what the requirements select: in the state " +
                     describe(meaning.witness) + " it selects " + meaning.compiled_selects +
                     " where the requirements select " + meaning.required_selects,
                 tree->root, path);
  f.adaptable = adaptable;
  f.witness = meaning.witness;
  if (!meaning.required_by.empty()) f.requirements = {meaning.required_by};
  f.alternatives = meaning.alternatives;
  return true;
}

}  // namespace

void check_selection(Context& ctx, Prover& prover, const std::string& adaptable,
                     std::set<std::string>& checked_alternatives) {
  // Shape first, into a scratch context: a Fig. 4 tree gets the precise per-branch checks.
  Context shape(ctx.mission(), ctx.compiled());
  std::optional<Selector> selector = read_selector(shape, adaptable);
  if (selector && shape.findings().empty()) {
    SelectionCheck(ctx, prover, adaptable, std::move(*selector), checked_alternatives).run();
    return;
  }
  if (check_by_meaning(ctx, prover, adaptable, shape.findings(), checked_alternatives)) return;
  for (Finding& f : shape.findings()) ctx.findings().push_back(std::move(f));
  if (selector)
    SelectionCheck(ctx, prover, adaptable, std::move(*selector), checked_alternatives).run();
}

}  // namespace uabt::conform
