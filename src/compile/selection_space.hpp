#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/value.hpp"
#include "fretish/domain.hpp"
#include "fretish/expr.hpp"

namespace uabt::compile {

// The state space of one adaptable node's selection, cut into cells on which every atom of its
// guards (and of the domain's assumptions) keeps one truth value. A cell is one piece per
// dimension; the selection is constant on a cell, so a decision structure that is right on
// every cell is right in every state.
struct Dimension {
  enum class Kind {
    boolean,      // a condition: pieces false, true
    ordered,      // an integer or real variable cut at the constants its atoms compare with
    enumeration,  // an enum variable: one piece per literal
    opaque,       // an atom over several variables: pieces false, true (taken as free)
  };
  // A piece of an ordered dimension: the point `at` or the open interval (below, above) between
  // two neighbouring cuts (an end at infinity when unbounded).
  struct Piece {
    double weight = 0;  // measure: integer points, real length, 1 for a literal or a truth value
    bool point = false;
    double at = 0, below = 0, above = 0;
    bool open_below = false, open_above = false;  // unbounded side
    std::string text;  // the cut as written (a point; an interval's upper end), the literal
  };

  Kind kind = Kind::boolean;
  std::string name;           // variable, or the atom's FRETISH text (opaque)
  fretish::ExprPtr atom;      // opaque: the atom itself
  bool integer = false;       // ordered: integer variable
  std::vector<Piece> pieces;  // in order (ordered: ascending)
};

// What an atom decides on a dimension: the pieces where it holds.
struct AtomTruth {
  std::size_t dimension = 0;
  std::vector<bool> holds;  // per piece
};

// A guard or assumption over dimensions: and/or/not over atoms (rewritten as Algorithm 1
// builds them), evaluated per cell.
struct CellExpr {
  enum class Op { atom, constant, negation, conjunction, disjunction };
  Op op = Op::constant;
  bool value = false;    // constant
  std::size_t atom = 0;  // index into SelectionSpace::atoms
  std::vector<CellExpr> args;
};

struct SelectionSpace {
  std::vector<Dimension> dimensions;
  std::vector<AtomTruth> atoms;
  std::vector<CellExpr> guards;  // per requirement, priority order (default: true)
  // Cells that satisfy the assumptions: pieces[c * dimensions.size() + d].
  std::vector<std::uint32_t> pieces;
  std::vector<double> weight;  // per cell
  std::vector<int> label;      // per cell: first requirement whose guard holds, -1 none
  std::size_t cells() const { return weight.size(); }
  std::uint32_t piece(std::size_t cell, std::size_t dim) const {
    return pieces[cell * dimensions.size() + dim];
  }
  bool atom_holds(std::size_t atom, std::size_t cell) const {
    const AtomTruth& a = atoms[atom];
    return a.holds[piece(cell, a.dimension)];
  }
};

// The condition's value on a cell, evaluated as the compiled tree ticks it: short-circuit, left
// to right (Algorithm 1: Sequence, Fallback, Inverter). `ticked`, when given, counts the atoms
// (condition nodes) evaluated.
bool evaluate_on_cell(const SelectionSpace& space, const CellExpr& e, std::size_t cell,
                      int* ticked = nullptr);

// A state of the cell: one value per variable dimension (inside the piece; integers whole).
// nullopt when a dimension is an opaque atom (no single variable to set).
std::optional<State> cell_state(const SelectionSpace& space, std::size_t cell);

// Builds the space of `guards` (nullptr: a default) under `domain`. nullopt when it has more
// than `max_cells` cells before the assumptions are applied.
std::optional<SelectionSpace> build_selection_space(const std::vector<fretish::ExprPtr>& guards,
                                                    const fretish::Domain& domain,
                                                    std::size_t max_cells = 1u << 20);

}  // namespace uabt::compile
