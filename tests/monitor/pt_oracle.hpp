#pragma once
// An evaluator of FRET's past-time formula language (the `ptExpanded` strings of its exports and
// of semantics.json), written for tests only and independent of src/monitor: it reads the whole
// trace at once and evaluates every operator by its definition, with no incremental state.
//   Boolean: ! & | xor -> => <-> <=>, TRUE FALSE true false
//   Temporal: Y Z H O (unary), S T (binary), bounded O[..] H[..] with [<=n] [<n] [=n] [a,b],
//             where n may be a sum such as 5+1
//   Arithmetic and relations: + - * / mod ^ unary -, = != < <= > >=; a '-' against a digit is
//   the sign of the number (FRET's NUMBER); `-x ^ 2` is -(x ^ 2); on integers `/` and `mod`
//   truncate toward zero (FRET's targets), numbers written without '.' or 'e' are integers
//   Functions: absReal absInt minReal maxReal minInt maxInt ite preBool preInt preReal
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace uabt::testing {

struct OracleValue {
  bool is_number = false;
  bool truth = false;
  double number = 0;
  bool integer = false;  // a number of integer type
};

// One tick of a trace: variable name -> value (booleans with is_number false).
using OracleState = std::map<std::string, OracleValue>;

class PtFormula {
 public:
  // Throws std::runtime_error with the position on a syntax error.
  static PtFormula parse(const std::string& text);
  // The formula's truth value at every tick of `trace`.
  std::vector<bool> evaluate(const std::vector<OracleState>& trace) const;

  struct Node;

 private:
  std::shared_ptr<const Node> root_;
};

// Replaces every "$name$" of a semantics.json template.
std::string instantiate(std::string formula, const std::map<std::string, std::string>& values);

}  // namespace uabt::testing
