#include "pt_oracle.hpp"

#include <cctype>
#include <cmath>
#include <stdexcept>

namespace uabt::testing {

struct PtFormula::Node {
  std::string op;  // "var", "num", "const", "call", or the operator
  std::string name;
  double number = 0;
  bool integer = false;  // "num": written without '.' or 'e'
  bool truth = false;
  long lo = 0, hi = 0;  // bounded temporal operators: distances lo..hi
  bool bounded = false;
  std::vector<std::shared_ptr<const Node>> args;
};

namespace {

using NodePtr = std::shared_ptr<const PtFormula::Node>;
using Node = PtFormula::Node;

class Parser {
 public:
  explicit Parser(const std::string& text) : s_(text) {}

  NodePtr parse() {
    NodePtr n = iff();
    skip();
    if (i_ != s_.size()) fail("trailing input");
    return n;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(what + " at offset " + std::to_string(i_) + " of: " + s_);
  }
  void skip() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool eat(const std::string& token) {
    skip();
    if (s_.compare(i_, token.size(), token) != 0) return false;
    // A word operator must not run into an identifier.
    if (std::isalpha(static_cast<unsigned char>(token.back())) && i_ + token.size() < s_.size() &&
        (std::isalnum(static_cast<unsigned char>(s_[i_ + token.size()])) ||
         s_[i_ + token.size()] == '_'))
      return false;
    i_ += token.size();
    return true;
  }
  static NodePtr make(std::string op, std::vector<NodePtr> args) {
    auto n = std::make_shared<Node>();
    n->op = std::move(op);
    n->args = std::move(args);
    return n;
  }

  NodePtr iff() {
    NodePtr l = implies();
    while (true) {
      if (eat("<->") || eat("<=>"))
        l = make("<->", {l, implies()});
      else
        return l;
    }
  }
  NodePtr implies() {
    NodePtr l = xor_();
    if (eat("->") || eat("=>")) return make("->", {l, implies()});  // right-associative
    return l;
  }
  NodePtr xor_() {
    NodePtr l = or_();
    while (eat("xor")) l = make("xor", {l, or_()});
    return l;
  }
  NodePtr or_() {
    NodePtr l = and_();
    while (eat("|")) l = make("|", {l, and_()});
    return l;
  }
  NodePtr and_() {
    NodePtr l = since();
    while (eat("&")) l = make("&", {l, since()});
    return l;
  }
  NodePtr since() {
    NodePtr l = relation();
    while (true) {
      skip();
      if (eat("S")) {
        l = make("S", {l, relation()});
      } else if (eat("T")) {
        l = make("T", {l, relation()});
      } else {
        return l;
      }
    }
  }
  NodePtr relation() {
    NodePtr l = additive();
    for (const char* op : {"<=", ">=", "!=", "=", "<", ">"}) {
      skip();
      // "<=" must not be read from "<=>" nor "<" from "<->"
      if (s_.compare(i_, 3, "<=>") == 0 || s_.compare(i_, 3, "<->") == 0) return l;
      if (s_.compare(i_, 2, "->") == 0 || s_.compare(i_, 2, "=>") == 0) return l;
      if (eat(op)) return make(op, {l, additive()});
    }
    return l;
  }
  NodePtr additive() {
    NodePtr l = multiplicative();
    while (true) {
      skip();
      if (s_.compare(i_, 2, "->") == 0) return l;
      if (eat("+"))
        l = make("+", {l, multiplicative()});
      else if (eat("-"))
        l = make("-", {l, multiplicative()});
      else
        return l;
    }
  }
  NodePtr multiplicative() {
    NodePtr l = power();
    while (true) {
      if (eat("*"))
        l = make("*", {l, power()});
      else if (eat("/"))
        l = make("/", {l, power()});
      else if (eat("mod"))
        l = make("mod", {l, power()});
      else
        return l;
    }
  }
  bool at_signed_number() {
    skip();
    return i_ + 1 < s_.size() && s_[i_] == '-' &&
           std::isdigit(static_cast<unsigned char>(s_[i_ + 1]));
  }
  NodePtr power() {
    // LTL.g4: unary '-' binds looser than '^' (-x ^ 2 is -(x ^ 2)), but a NUMBER keeps its sign.
    if (!at_signed_number() && eat("-")) return make("neg", {power()});
    NodePtr l = unary();
    if (eat("^")) return make("^", {l, power()});
    return l;
  }
  long bound_number() {
    long value = 0;
    bool any = false;
    do {
      skip();
      const std::size_t start = i_;
      while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
      if (start == i_) fail("number expected in a bound");
      value += std::stol(s_.substr(start, i_ - start));
      any = true;
    } while (eat("+"));
    if (!any) fail("bound expected");
    return value;
  }
  NodePtr unary() {
    if (eat("!") || eat("~")) return make("!", {unary()});
    if (!at_signed_number() && eat("-")) return make("neg", {unary()});
    skip();
    for (const char* op : {"Y", "Z", "H", "O"}) {
      if (i_ < s_.size() && s_[i_] == op[0] && i_ + 1 < s_.size() &&
          (s_[i_ + 1] == ' ' || s_[i_ + 1] == '(' || s_[i_ + 1] == '[')) {
        ++i_;
        auto n = std::make_shared<Node>();
        n->op = op;
        if (s_[i_] == '[') {
          ++i_;
          n->bounded = true;
          if (eat("<=")) {
            n->lo = 0;
            n->hi = bound_number();
          } else if (eat("<")) {
            n->lo = 0;
            n->hi = bound_number() - 1;
          } else if (eat("=")) {
            n->lo = n->hi = bound_number();
          } else {
            n->lo = bound_number();
            if (!eat(",")) fail("',' expected in a bound");
            n->hi = bound_number();
          }
          if (!eat("]")) fail("']' expected");
        }
        n->args.push_back(unary());
        return n;
      }
    }
    return primary();
  }
  NodePtr primary() {
    skip();
    if (eat("(")) {
      NodePtr n = iff();
      if (!eat(")")) fail("')' expected");
      return n;
    }
    if (at_signed_number() ||
        (i_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[i_])) || s_[i_] == '.'))) {
      const std::size_t start = i_;
      if (s_[i_] == '-') ++i_;
      while (i_ < s_.size() &&
             (std::isdigit(static_cast<unsigned char>(s_[i_])) || s_[i_] == '.' || s_[i_] == 'e'))
        ++i_;
      auto n = std::make_shared<Node>();
      n->op = "num";
      n->number = std::stod(s_.substr(start, i_ - start));
      n->integer = s_.substr(start, i_ - start).find_first_of(".e") == std::string::npos;
      return n;
    }
    if (i_ < s_.size() && (std::isalpha(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_')) {
      const std::size_t start = i_;
      while (i_ < s_.size() &&
             (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_' || s_[i_] == '.'))
        ++i_;
      const std::string word = s_.substr(start, i_ - start);
      auto n = std::make_shared<Node>();
      if (word == "TRUE" || word == "true" || word == "FALSE" || word == "false") {
        n->op = "const";
        n->truth = word == "TRUE" || word == "true";
        return n;
      }
      if (eat("(")) {
        n->op = "call";
        n->name = word;
        if (!eat(")")) {
          do n->args.push_back(iff());
          while (eat(","));
          if (!eat(")")) fail("')' expected after arguments");
        }
        return n;
      }
      n->op = "var";
      n->name = word;
      return n;
    }
    fail("expression expected");
  }

  const std::string& s_;
  std::size_t i_ = 0;
};

using Column = std::vector<OracleValue>;

OracleValue boolean(bool b) {
  return {false, b, 0, false};
}
OracleValue number(double x, bool integer = false) {
  return {true, false, x, integer};
}

Column eval(const Node& n, const std::vector<OracleState>& trace) {
  const std::size_t len = trace.size();
  Column out(len);
  std::vector<Column> a;
  for (const auto& arg : n.args) a.push_back(eval(*arg, trace));
  const auto truth = [&](std::size_t i, std::size_t t) {
    if (a[i][t].is_number) throw std::runtime_error("boolean expected for " + n.op);
    return a[i][t].truth;
  };
  const auto ints = [&](std::size_t t) {
    for (const Column& c : a)
      if (!c[t].integer) return false;
    return true;
  };
  const auto num = [&](std::size_t i, std::size_t t) {
    if (!a[i][t].is_number) throw std::runtime_error("number expected for " + n.op);
    return a[i][t].number;
  };
  for (std::size_t t = 0; t < len; ++t) {
    const std::string& op = n.op;
    if (op == "var") {
      const auto it = trace[t].find(n.name);
      if (it == trace[t].end()) throw std::runtime_error("no value for " + n.name);
      out[t] = it->second;
    } else if (op == "num") {
      out[t] = number(n.number, n.integer);
    } else if (op == "const") {
      out[t] = boolean(n.truth);
    } else if (op == "!") {
      out[t] = boolean(!truth(0, t));
    } else if (op == "&") {
      out[t] = boolean(truth(0, t) && truth(1, t));
    } else if (op == "|") {
      out[t] = boolean(truth(0, t) || truth(1, t));
    } else if (op == "xor") {
      out[t] = boolean(truth(0, t) != truth(1, t));
    } else if (op == "->") {
      out[t] = boolean(!truth(0, t) || truth(1, t));
    } else if (op == "<->") {
      out[t] = boolean(truth(0, t) == truth(1, t));
    } else if (op == "Y") {
      out[t] = boolean(t > 0 && truth(0, t - 1));
    } else if (op == "Z") {
      out[t] = boolean(t == 0 || truth(0, t - 1));
    } else if ((op == "H" || op == "O") && !n.bounded) {
      bool all = true, any = false;
      for (std::size_t j = 0; j <= t; ++j) {
        all = all && truth(0, j);
        any = any || truth(0, j);
      }
      out[t] = boolean(op == "H" ? all : any);
    } else if (op == "H" || op == "O") {
      // Distances lo..hi that lie within the trace.
      bool all = true, any = false;
      for (long k = n.lo; k <= n.hi; ++k) {
        if (k < 0 || static_cast<std::size_t>(k) > t) continue;
        const bool v = truth(0, t - static_cast<std::size_t>(k));
        all = all && v;
        any = any || v;
      }
      out[t] = boolean(op == "H" ? all : any);
    } else if (op == "S" || op == "T") {
      // a S b: b at some j <= t and a at every point after j up to t. a T b = !(!a S !b).
      const bool want = op == "S";
      bool found = false;
      for (std::size_t j = 0; j <= t && !found; ++j) {
        if (truth(1, j) != want) continue;
        bool after = true;
        for (std::size_t k = j + 1; k <= t; ++k) after = after && (truth(0, k) == want);
        found = after;
      }
      out[t] = boolean(want ? found : !found);
    } else if (op == "=" || op == "!=") {
      const bool same =
          a[0][t].is_number ? a[0][t].number == num(1, t) : truth(0, t) == truth(1, t);
      out[t] = boolean(op == "=" ? same : !same);
    } else if (op == "<") {
      out[t] = boolean(num(0, t) < num(1, t));
    } else if (op == "<=") {
      out[t] = boolean(num(0, t) <= num(1, t));
    } else if (op == ">") {
      out[t] = boolean(num(0, t) > num(1, t));
    } else if (op == ">=") {
      out[t] = boolean(num(0, t) >= num(1, t));
    } else if (op == "+") {
      out[t] = number(num(0, t) + num(1, t), ints(t));
    } else if (op == "-") {
      out[t] = number(num(0, t) - num(1, t), ints(t));
    } else if (op == "*") {
      out[t] = number(num(0, t) * num(1, t), ints(t));
    } else if (op == "/") {
      // Integers: C's division, truncated toward zero.
      if (ints(t))
        out[t] = number(static_cast<double>(static_cast<long long>(num(0, t)) /
                                            static_cast<long long>(num(1, t))),
                        true);
      else
        out[t] = number(num(0, t) / num(1, t));
    } else if (op == "mod") {
      if (ints(t))
        out[t] = number(static_cast<double>(static_cast<long long>(num(0, t)) %
                                            static_cast<long long>(num(1, t))),
                        true);
      else
        out[t] = number(std::fmod(num(0, t), num(1, t)));
    } else if (op == "^") {
      out[t] = number(std::pow(num(0, t), num(1, t)), ints(t) && num(1, t) >= 0);
    } else if (op == "neg") {
      out[t] = number(-num(0, t), a[0][t].integer);
    } else if (op == "call") {
      const std::string& f = n.name;
      if (f == "absReal" || f == "absInt") {
        out[t] = number(std::fabs(num(0, t)));
      } else if (f == "minReal" || f == "minInt") {
        out[t] = number(std::fmin(num(0, t), num(1, t)));
      } else if (f == "maxReal" || f == "maxInt") {
        out[t] = number(std::fmax(num(0, t), num(1, t)));
      } else if (f == "ite") {
        out[t] = truth(0, t) ? a[1][t] : a[2][t];
      } else if (f == "preBool" || f == "preInt" || f == "preReal") {
        out[t] = t == 0 ? a[0][t] : a[1][t - 1];
      } else {
        throw std::runtime_error("unknown function " + f);
      }
    } else {
      throw std::runtime_error("unknown operator " + op);
    }
  }
  return out;
}

}  // namespace

PtFormula PtFormula::parse(const std::string& text) {
  PtFormula f;
  f.root_ = Parser(text).parse();
  return f;
}

std::vector<bool> PtFormula::evaluate(const std::vector<OracleState>& trace) const {
  const Column c = eval(*root_, trace);
  std::vector<bool> out;
  for (const OracleValue& v : c) {
    if (v.is_number) throw std::runtime_error("the formula is a number");
    out.push_back(v.truth);
  }
  return out;
}

std::string instantiate(std::string formula, const std::map<std::string, std::string>& values) {
  for (const auto& [name, value] : values) {
    const std::string key = "$" + name + "$";
    for (std::size_t at = formula.find(key); at != std::string::npos;
         at = formula.find(key, at + value.size()))
      formula.replace(at, key.size(), value);
  }
  return formula;
}

}  // namespace uabt::testing
