#pragma once
#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

namespace uabt::monitor {

// A past-time temporal formula as a DAG whose nodes refer only to earlier nodes, so one pass
// over the nodes in index order evaluates a tick. Every operator keeps constant state: a bit,
// or a counter that saturates at its bound. The one exception is `exactly_ago`, a ring of k+1
// bits, which FRET's "only … after N" needs (see templates.cpp).
enum class Op : std::uint8_t {
  input,           // the boolean input `slot` of this tick
  constant,        // `k` != 0
  negation,        // !a
  conjunction,     // a & b
  disjunction,     // a | b
  yesterday,       // Y a   (false at the first tick)
  weak_yesterday,  // Z a   (true at the first tick)
  historically,    // H a
  once,            // O a
  since,           // a S b
  once_within,     // O[<=k] a: a held at distance 0..k
  since_at_least,  // a S[>=k] b: b held at distance >= k and a at every point after it
  exactly_ago,     // O[=k] a
};

struct Node {
  Op op = Op::constant;
  int a = -1, b = -1;
  std::uint64_t k = 0;
};

class Formula {
 public:
  int input(int slot);
  int constant(bool value);
  int negation(int a);
  int conjunction(int a, int b);
  int disjunction(int a, int b);
  int implication(int a, int b) { return disjunction(negation(a), b); }
  int yesterday(int a);
  int weak_yesterday(int a);
  int historically(int a);
  int once(int a);
  int since(int a, int b);
  int once_within(int a, std::uint64_t k);
  // O[<k] a: distance 0..k-1 (false when k is 0).
  int once_below(int a, std::uint64_t k);
  int since_at_least(int a, int b, std::uint64_t k);
  int exactly_ago(int a, std::uint64_t k);
  int first_tick();  // FTP: !(Y true)

  const std::vector<Node>& nodes() const { return nodes_; }
  int inputs() const { return inputs_; }

 private:
  int add(Node n);
  std::vector<Node> nodes_;
  std::map<std::tuple<Op, int, int, std::uint64_t>, int> index_;  // shares equal subformulas
  int inputs_ = 0;
};

// The state of a Formula as plain words, and the one past-time step over it: the monitor keeps
// one state, the model checker hashes, copies and encodes many. One word per Y/Z/H/O/S bit or
// O[<=k] age, two for S[>=k] (live, age) and 2 + k + 1 for O[=k] (write index, ticks seen up
// to k, the ring).
class PastTimeLayout {
 public:
  explicit PastTimeLayout(const Formula& formula, int root);
  std::vector<std::uint64_t> initial() const;
  // One tick: updates `state`, returns the formula's value. `values` receives each node's.
  bool step(const bool* inputs, std::vector<std::uint64_t>& state, std::vector<char>& values) const;
  std::size_t words() const { return words_; }
  std::size_t inputs() const { return inputs_; }  // the boolean inputs step reads

 private:
  std::vector<Node> nodes_;
  std::vector<std::size_t> offset_;
  std::size_t words_ = 0;
  std::size_t inputs_ = 0;
  int root_ = 0;
};

// The running state of one formula: call step() once per tick with that tick's inputs.
class FormulaMonitor {
 public:
  explicit FormulaMonitor(const Formula& formula, int root)
      : layout_(formula, root), state_(layout_.initial()), value_(formula.nodes().size(), 0) {}
  bool step(const bool* inputs) { return layout_.step(inputs, state_, value_); }
  // The value node `node` of the formula took at the last step.
  bool value(int node) const { return value_[static_cast<std::size_t>(node)] != 0; }

 private:
  PastTimeLayout layout_;
  std::vector<std::uint64_t> state_;
  std::vector<char> value_;
};

}  // namespace uabt::monitor
