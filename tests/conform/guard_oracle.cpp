// Ticks condition-checking subtrees directly; see guard_oracle.hpp.
#include "guard_oracle.hpp"

#include <cctype>
#include <cmath>
#include <functional>
#include <set>
#include <sstream>
#include <stdexcept>

#include "smt/evaluate.hpp"

namespace uabt::testing::oracle {

namespace {

struct Invalid : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A script value as BT.CPP's Any holds it in a condition: a number, a string or a bool.
struct ScriptValue {
  enum { number, string, boolean } kind = number;
  double n = 0;
  std::string s;
  bool b = false;
};

// Evaluates BT.CPP script conditions directly from the text.
class ScriptEval {
 public:
  ScriptEval(const std::string& code, const State& state) : code_(code), state_(state) {}

  bool run() {
    ScriptValue v = logical();
    skip_space();
    if (pos_ != code_.size()) throw Invalid("trailing text in script");
    if (v.kind != ScriptValue::boolean) throw Invalid("script is not a condition");
    return v.b;
  }

 private:
  void skip_space() {
    while (pos_ < code_.size() && std::isspace(static_cast<unsigned char>(code_[pos_]))) ++pos_;
  }
  bool eat(const std::string& op) {
    skip_space();
    if (code_.compare(pos_, op.size(), op) != 0) return false;
    // "<" must not take the first half of "<=", "!" not of "!=".
    if ((op == "<" || op == ">" || op == "!") && pos_ + 1 < code_.size() && code_[pos_ + 1] == '=')
      return false;
    pos_ += op.size();
    return true;
  }
  static bool truth(const ScriptValue& v) {
    if (v.kind != ScriptValue::boolean) throw Invalid("logic on a non-boolean");
    return v.b;
  }
  static ScriptValue of_bool(bool b) {
    ScriptValue v;
    v.kind = ScriptValue::boolean;
    v.b = b;
    return v;
  }

  ScriptValue logical() {
    ScriptValue lhs = comparison();
    for (;;) {
      if (eat("&&")) {
        const bool r = truth(comparison());
        lhs = of_bool(truth(lhs) && r);
      } else if (eat("||")) {
        const bool r = truth(comparison());
        lhs = of_bool(truth(lhs) || r);
      } else {
        return lhs;
      }
    }
  }

  static bool compare(const ScriptValue& a, const std::string& op, const ScriptValue& b) {
    if (a.kind != b.kind) throw Invalid("comparison of different kinds");
    if (a.kind == ScriptValue::number) {
      if (op == "==") return a.n == b.n;
      if (op == "!=") return a.n != b.n;
      if (op == "<") return a.n < b.n;
      if (op == "<=") return a.n <= b.n;
      if (op == ">") return a.n > b.n;
      return a.n >= b.n;
    }
    if (op != "==" && op != "!=") throw Invalid("ordering of non-numbers");
    const bool same = a.kind == ScriptValue::string ? a.s == b.s : a.b == b.b;
    return op == "==" ? same : !same;
  }

  ScriptValue comparison() {
    ScriptValue lhs = sum();
    bool all = true, any = false;
    for (;;) {
      std::string op;
      for (const char* candidate : {"==", "!=", "<=", ">=", "<", ">"})
        if (eat(candidate)) {
          op = candidate;
          break;
        }
      if (op.empty()) break;
      ScriptValue rhs = sum();
      all = all && compare(lhs, op, rhs);
      any = true;
      lhs = rhs;
    }
    return any ? of_bool(all) : lhs;
  }

  static double number(const ScriptValue& v) {
    if (v.kind != ScriptValue::number) throw Invalid("arithmetic on a non-number");
    return v.n;
  }
  ScriptValue sum() {
    ScriptValue lhs = product();
    for (;;) {
      if (eat("+"))
        lhs.n = number(lhs) + number(product());
      else if (eat("-"))
        lhs.n = number(lhs) - number(product());
      else
        return lhs;
    }
  }
  ScriptValue product() {
    ScriptValue lhs = prefix();
    for (;;) {
      if (eat("*"))
        lhs.n = number(lhs) * number(prefix());
      else if (eat("/"))
        lhs.n = number(lhs) / number(prefix());
      else
        return lhs;
    }
  }
  ScriptValue prefix() {
    if (eat("-")) {
      ScriptValue v = atom();
      v.n = -number(v);
      return v;
    }
    if (eat("!")) return of_bool(!truth(atom()));
    return atom();
  }
  ScriptValue atom() {
    skip_space();
    if (pos_ >= code_.size()) throw Invalid("script ends early");
    const char c = code_[pos_];
    if (c == '(') {
      ++pos_;
      ScriptValue v = logical();
      if (!eat(")")) throw Invalid("missing )");
      return v;
    }
    if (c == '\'') {
      const std::size_t close = code_.find('\'', pos_ + 1);
      if (close == std::string::npos) throw Invalid("unterminated string");
      ScriptValue v;
      v.kind = ScriptValue::string;
      v.s = code_.substr(pos_ + 1, close - pos_ - 1);
      pos_ = close + 1;
      return v;
    }
    if (std::isdigit(static_cast<unsigned char>(c))) {
      std::size_t used = 0;
      ScriptValue v;
      v.n = std::stod(code_.substr(pos_), &used);
      pos_ += used;
      return v;
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == '@') {
      std::size_t end = pos_ + 1;
      while (end < code_.size() &&
             (std::isalnum(static_cast<unsigned char>(code_[end])) || code_[end] == '_'))
        ++end;
      std::string name = code_.substr(pos_, end - pos_);
      pos_ = end;
      if (name == "true" || name == "false") return of_bool(name == "true");
      if (name[0] == '@') name.erase(0, 1);
      const Value* value = find_value(state_, name);
      if (value == nullptr) throw Invalid("undefined blackboard entry " + name);
      ScriptValue v;
      switch (value->kind) {
        case Value::Kind::boolean: return of_bool(value->boolean);
        case Value::Kind::integer: v.n = static_cast<double>(value->integer); return v;
        case Value::Kind::real: v.n = value->real; return v;
        case Value::Kind::enumeration:
          v.kind = ScriptValue::string;
          v.s = value->text;
          return v;
      }
    }
    throw Invalid(std::string("unexpected '") + c + "' in script");
  }

  const std::string& code_;
  const State& state_;
  std::size_t pos_ = 0;
};

bool tick(const bt::Document& doc, const bt::Node& n, const State& state, int depth) {
  if (depth > 256) throw Invalid("too deep");
  for (const auto& [key, value] : n.attributes)
    if (!key.empty() && key[0] == '_' && key != "_autoremap" && key != "__shared_blackboard")
      throw Invalid("pre/post condition");
  const std::string kind = n.kind();
  auto only_child = [&]() -> const bt::Node& {
    if (n.children.size() != 1) throw Invalid(kind + " needs exactly one child");
    return n.children[0];
  };
  if (kind == "Sequence" || kind == "ReactiveSequence" || kind == "Fallback" ||
      kind == "ReactiveFallback") {
    if (n.children.empty()) throw Invalid(kind + " without children");
    // Every child is ticked (guards are pure): a broken child is broken whatever the state.
    const bool conjunction = kind == "Sequence" || kind == "ReactiveSequence";
    bool result = conjunction;
    for (const auto& c : n.children) {
      const bool v = tick(doc, c, state, depth + 1);
      result = conjunction ? (result && v) : (result || v);
    }
    return result;
  }
  if (kind == "Inverter") return !tick(doc, only_child(), state, depth + 1);
  if (kind == "ForceSuccess" || kind == "ForceFailure") {
    tick(doc, only_child(), state, depth + 1);
    return kind == "ForceSuccess";
  }
  if (kind == "AlwaysSuccess" || kind == "AlwaysFailure") {
    if (!n.children.empty()) throw Invalid("leaf with children");
    return kind == "AlwaysSuccess";
  }
  if (kind == "ScriptCondition") {
    const std::string* code = n.attribute("code");
    if (code == nullptr || !n.children.empty()) throw Invalid("bad ScriptCondition");
    return ScriptEval(*code, state).run();
  }
  if (kind == "SubTree") {
    const std::string* id = n.attribute("ID");
    const bt::TreeDef* t = id ? doc.find_tree(*id) : nullptr;
    if (t == nullptr || !n.children.empty()) throw Invalid("bad SubTree");
    return tick(doc, t->root, state, depth + 1);
  }
  static const std::set<std::string> not_conditions = {"Adaptable",
                                                       "Repeat",
                                                       "RetryUntilSuccessful",
                                                       "Parallel",
                                                       "ParallelAll",
                                                       "Script",
                                                       "Sleep",
                                                       "SetBlackboard",
                                                       "IfThenElse",
                                                       "WhileDoElse",
                                                       "SequenceWithMemory",
                                                       "SequenceStar",
                                                       "KeepRunningUntilFailure",
                                                       "RunOnce",
                                                       "Delay",
                                                       "Timeout"};
  if (not_conditions.count(kind) || !n.children.empty()) throw Invalid(kind + " is no condition");
  for (const auto& [key, value] : n.attributes)
    if (key != "name" && !(key == "ID" && n.tag != kind)) throw Invalid("condition with ports");
  const Value* v = find_value(state, kind);
  if (v == nullptr || v->kind != Value::Kind::boolean) throw Invalid("no boolean " + kind);
  return v->boolean;
}

std::string format_number(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

// Condition leaves and script constants of the selection trees' guards.
void collect(const bt::Document& doc, const bt::Node& n, std::set<std::string>& leaves,
             std::set<double>& constants, int depth) {
  if (depth > 256) return;
  if (n.kind() == "ScriptCondition") {
    if (const std::string* code = n.attribute("code")) {
      for (std::size_t i = 0; i < code->size(); ++i) {
        if (!std::isdigit(static_cast<unsigned char>((*code)[i]))) continue;
        if (i > 0 &&
            (std::isalnum(static_cast<unsigned char>((*code)[i - 1])) || (*code)[i - 1] == '_'))
          continue;
        std::size_t used = 0;
        const double c = std::stod(code->substr(i), &used);
        constants.insert(c);
        constants.insert(-c);
        i += used;
      }
    }
    return;
  }
  if (n.kind() == "SubTree") {
    const std::string* id = n.attribute("ID");
    if (const bt::TreeDef* t = id ? doc.find_tree(*id) : nullptr)
      collect(doc, t->root, leaves, constants, depth + 1);
    return;
  }
  if (n.children.empty()) leaves.insert(n.kind());
  for (const auto& c : n.children) collect(doc, c, leaves, constants, depth + 1);
}

const bt::Node* guard_of(const bt::Node& branch) {
  return branch.children.size() == 2 ? &branch.children[0] : nullptr;
}

std::vector<State> states_for(const bt::Document& a, const bt::Document& b,
                              const std::vector<std::string>& adaptables,
                              const fretish::Domain& domain) {
  std::set<std::string> leaves;
  std::set<double> constants;
  for (const bt::Document* doc : {&a, &b})
    for (const auto& id : adaptables)
      if (const bt::TreeDef* t = doc->find_tree(id))
        for (const auto& branch : t->root.children)
          if (const bt::Node* g = guard_of(branch)) collect(*doc, *g, leaves, constants, 0);
  std::vector<std::string> extra;
  for (const auto& leaf : leaves)
    if (domain.find(leaf) == nullptr && leaf != "AlwaysSuccess" && leaf != "AlwaysFailure")
      extra.push_back(leaf);
  return sample_states(domain, extra, {constants.begin(), constants.end()});
}

}  // namespace

std::optional<bool> tick_guard(const bt::Document& doc, const bt::Node& guard, const State& state) {
  try {
    return tick(doc, guard, state, 0);
  } catch (const Invalid&) {
    return std::nullopt;
  }
}

std::vector<State> sample_states(const fretish::Domain& domain,
                                 const std::vector<std::string>& extra_booleans,
                                 const std::vector<double>& constants) {
  std::vector<std::pair<std::string, std::vector<Value>>> axes;
  for (const auto& v : domain.variables) {
    std::vector<Value> values;
    switch (v.type) {
      case fretish::VarType::boolean: values = {Value::of_bool(false), Value::of_bool(true)}; break;
      case fretish::VarType::enumeration:
        for (const auto& literal : v.enum_values) values.push_back(Value::of_enum(literal));
        break;
      case fretish::VarType::integer:
      case fretish::VarType::real: {
        const double lo = v.lower.empty() ? -1e6 : std::stod(v.lower);
        const double hi = v.upper.empty() ? 1e6 : std::stod(v.upper);
        std::set<double> points{lo, hi};
        const bool integer = v.type == fretish::VarType::integer;
        if (integer && hi - lo <= 16) {
          for (double x = lo; x <= hi; x += 1) points.insert(x);
        } else {
          for (double c : constants)
            for (double d : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
              const double x = integer ? std::round(c + d) : c + d;
              if (x >= lo && x <= hi) points.insert(x);
            }
        }
        for (double x : points)
          values.push_back(integer ? Value::of_int(static_cast<std::int64_t>(x))
                                   : Value::of_real(x, format_number(x)));
        break;
      }
    }
    axes.emplace_back(v.name, std::move(values));
  }
  for (const auto& name : extra_booleans)
    axes.emplace_back(name, std::vector<Value>{Value::of_bool(false), Value::of_bool(true)});

  std::vector<State> states;
  State current;
  std::function<void(std::size_t)> build = [&](std::size_t axis) {
    if (axis == axes.size()) {
      if (smt::satisfies_domain(domain, current)) states.push_back(current);
      return;
    }
    for (const auto& value : axes[axis].second) {
      current.emplace_back(axes[axis].first, value);
      build(axis + 1);
      current.pop_back();
    }
  };
  build(0);
  return states;
}

Verdict same_guards(const bt::Document& original, const bt::Document& mutant,
                    const std::vector<std::string>& adaptables, const fretish::Domain& domain) {
  const std::vector<State> states = states_for(original, mutant, adaptables, domain);
  for (const auto& id : adaptables) {
    const bt::TreeDef* a = original.find_tree(id);
    const bt::TreeDef* b = mutant.find_tree(id);
    if (a == nullptr || b == nullptr || a->root.children.size() != b->root.children.size())
      return {false, "the selection tree " + id + " lost or gained branches"};
    for (std::size_t i = 0; i < a->root.children.size(); ++i) {
      const bt::Node* ga = guard_of(a->root.children[i]);
      const bt::Node* gb = guard_of(b->root.children[i]);
      for (const State& s : states) {
        const std::optional<bool> va = ga ? tick_guard(original, *ga, s) : true;
        const std::optional<bool> vb = gb ? tick_guard(mutant, *gb, s) : true;
        if (!va)
          throw std::logic_error("the original guard of branch " + std::to_string(i) + " of " + id +
                                 " does not tick");
        if (!vb) return {false, "branch " + std::to_string(i) + " of " + id + " cannot tick"};
        if (*va != *vb) {
          std::string where;
          for (const auto& [name, value] : s) where += name + "=" + value.to_string() + " ";
          return {false, "branch " + std::to_string(i) + " of " + id + " differs at " + where};
        }
      }
    }
  }
  return {true, ""};
}

bool same_selection(const bt::Document& original, const bt::Document& mutant,
                    const std::vector<std::string>& adaptables, const fretish::Domain& domain) {
  const std::vector<State> states = states_for(original, mutant, adaptables, domain);
  auto selected = [](const bt::Document& doc, const bt::TreeDef& t,
                     const State& s) -> std::optional<std::string> {
    for (const auto& branch : t.root.children) {
      const bt::Node* g = guard_of(branch);
      const std::optional<bool> v = g ? tick_guard(doc, *g, s) : true;
      if (!v) return std::nullopt;
      if (*v && !branch.children.empty()) {
        const std::string* id = branch.children.back().attribute("ID");
        return id ? *id : std::string("?");
      }
    }
    return std::string();
  };
  for (const auto& id : adaptables) {
    const bt::TreeDef* a = original.find_tree(id);
    const bt::TreeDef* b = mutant.find_tree(id);
    if (a == nullptr || b == nullptr) return false;
    for (const State& s : states) {
      const auto sa = selected(original, *a, s), sb = selected(mutant, *b, s);
      if (!sa || !sb || *sa != *sb) return false;
    }
  }
  return true;
}

}  // namespace uabt::testing::oracle
