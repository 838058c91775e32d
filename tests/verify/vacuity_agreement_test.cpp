// guard-vacuous-atom against brute force: on random guards over a small domain, an occurrence
// is reported exactly when a constant can stand for it in every state, and with that constant.
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <memory>
#include <random>

#include "verify/mission_builder.hpp"

namespace uabt::testing {
namespace {

// A state of the domain below: A, B boolean, x in [0, 3], y in [0, 2].
struct Point {
  bool a, b;
  int x, y;
};

// A random guard, as text and as a function of the state with occurrence k forced.
struct Node {
  std::string op;  // "atom", "!", "&", "|", "xor", "->", "<->"
  std::function<bool(const Point&)> atom;
  int occurrence = -1;
  std::vector<std::unique_ptr<Node>> args;

  bool eval(const Point& p, int forced, bool value) const {
    if (op == "atom") return occurrence == forced ? value : atom(p);
    if (op == "!") return !args[0]->eval(p, forced, value);
    const bool l = args[0]->eval(p, forced, value), r = args[1]->eval(p, forced, value);
    if (op == "&") return l && r;
    if (op == "|") return l || r;
    if (op == "xor") return l != r;
    if (op == "->") return !l || r;
    return l == r;  // <->
  }
};

class GuardMaker {
 public:
  explicit GuardMaker(unsigned seed) : rng_(seed) {}

  // Builds a guard of about `atoms` atoms; `text` gets its FRETISH text, `columns` the column
  // of each occurrence (1-based, counted from `offset`).
  std::unique_ptr<Node> make(int atoms, std::string& text, std::vector<int>& columns, int offset) {
    auto node = std::make_unique<Node>();
    if (atoms <= 1) {
      node->op = "atom";
      node->occurrence = static_cast<int>(columns.size());
      columns.push_back(offset + static_cast<int>(text.size()) + 1);
      const int k = pick(0, 3);
      switch (pick(0, 4)) {
        case 0:
          text += "A";
          node->atom = [](const Point& p) { return p.a; };
          break;
        case 1:
          text += "B";
          node->atom = [](const Point& p) { return p.b; };
          break;
        case 2:
          text += "x > " + std::to_string(k);
          node->atom = [k](const Point& p) { return p.x > k; };
          break;
        case 3:
          text += "y = " + std::to_string(k % 3);
          node->atom = [k](const Point& p) { return p.y == k % 3; };
          break;
        default:
          text += "x + y < " + std::to_string(k + 1);
          node->atom = [k](const Point& p) { return p.x + p.y < k + 1; };
          break;
      }
      return node;
    }
    if (pick(0, 5) == 0) {
      node->op = "!";
      text += "!(";
      node->args.push_back(make(atoms, text, columns, offset));
      text += ")";
      return node;
    }
    static const char* const kOps[] = {"&", "|", "xor", "->", "<->", "&", "|"};
    node->op = kOps[pick(0, 6)];
    const int left = pick(1, atoms - 1);
    text += "(";
    node->args.push_back(make(left, text, columns, offset));
    text += " " + node->op + " ";
    node->args.push_back(make(atoms - left, text, columns, offset));
    text += ")";
    return node;
  }

 private:
  int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  std::mt19937 rng_;
};

std::vector<Point> every_point(bool assume_one_of) {
  std::vector<Point> out;
  for (const bool a : {false, true})
    for (const bool b : {false, true})
      for (int x = 0; x <= 3; ++x)
        for (int y = 0; y <= 2; ++y)
          if (!assume_one_of || !(a && b)) out.push_back({a, b, x, y});
  return out;
}

TEST(VacuityAgreement, ReportedOccurrencesAreExactlyThoseAConstantCanStandFor) {
  int guards = 0, vacuous = 0;
  for (unsigned seed = 1; seed <= 150; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    GuardMaker maker(seed);
    const bool assume = seed % 3 == 0;
    const std::string prefix = "R1: In exploration if ";
    std::string text;
    std::vector<int> columns;
    const auto guard =
        maker.make(2 + static_cast<int>(seed % 7), text, columns, static_cast<int>(prefix.size()));
    const std::vector<Point> points = every_point(assume);
    // Satisfiable guards only: an unsatisfiable one is reported as such instead.
    bool satisfiable = false;
    for (const Point& p : points) satisfiable = satisfiable || guard->eval(p, -1, false);
    if (!satisfiable) continue;
    ++guards;
    std::map<int, std::string> expected;  // column -> constant
    for (int k = 0; k < static_cast<int>(columns.size()); ++k) {
      for (const bool c : {true, false}) {
        bool same = true;
        for (const Point& p : points)
          same = same && guard->eval(p, -1, false) == guard->eval(p, k, c);
        if (same) {
          expected[columns[k]] = c ? "true" : "false";
          break;
        }
      }
    }
    const load::Mission m =
        make_mission(prefix + text + " Mission shall satisfy selected_alt = a\n" +
                         "Safe: In exploration Mission shall satisfy selected_alt = explore\n",
                     std::string("boolean A, B\ninteger x in [0, 3]\ninteger y in [0, 2]\n") +
                         (assume ? "assume one_of: !(A & B)\n" : ""));
    std::map<int, std::string> reported;
    const verify::Result result = verify_checked(m);
    for (const Finding* f : findings_of(result, "guard-vacuous-atom"))
      reported[f->location.column] =
          f->message.find("replaced by true") != std::string::npos ? "true" : "false";
    EXPECT_EQ(reported, expected) << text;
    vacuous += static_cast<int>(expected.size());
  }
  // The sample exercises both answers.
  EXPECT_GT(guards, 100);
  EXPECT_GT(vacuous, 20);
}

}  // namespace
}  // namespace uabt::testing
