#pragma once
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "verify/fraction.hpp"

namespace uabt::verify::detail {

// A real variable's range cut at every breakpoint the atoms draw: cell 2k is the point
// breaks[k], cell 2k+1 the open interval (breaks[k], breaks[k+1]).
struct RealAxis {
  std::string variable;
  std::vector<Fraction> breaks;  // sorted, distinct; front() and back() are the declared bounds

  std::size_t cells() const { return 2 * breaks.size() - 1; }
  static bool is_point(std::size_t cell) { return cell % 2 == 0; }
  const Fraction& from(std::size_t cell) const { return breaks[cell / 2]; }
  const Fraction& to(std::size_t cell) const { return breaks[(cell + 1) / 2]; }
  Fraction middle(std::size_t cell) const { return (from(cell) + to(cell)) / Fraction(2); }
  Fraction length(std::size_t cell) const { return to(cell) - from(cell); }
};

// a·x + b·y + c, with a = 1 (normalised, so that equal lines compare equal). Never parallel to
// an axis: an atom over one variable is a breakpoint instead.
struct Line {
  Fraction a, b, c;
  Fraction at(const Fraction& x, const Fraction& y) const { return a * x + b * y + c; }
  auto operator<=>(const Line&) const = default;
};

// One cell of a component: an open interval or a point (one variable), or an open polygon, an
// open segment or a point (two variables). Every atom over the component's variables has one
// truth value in a cell, so evaluating it at `point` decides the whole cell.
struct RealCell {
  Fraction weight;                               // length or area; 0 for a lower-dimensional cell
  std::vector<Fraction> point;                   // a point of its relative interior, per variable
  std::vector<std::size_t> axis_cell;            // per variable: the RealAxis cell that contains it
  std::vector<int> signs;                        // per line: -1, 0, +1 inside the cell
  std::vector<std::pair<double, double>> shape;  // vertices for pictures (x, y; y 0 in 1-D)
};

// A group of one real variable, or two that linear atoms relate, with its cells.
struct RealComponent {
  std::vector<RealAxis> axes;  // one or two
  std::vector<Line> lines;     // two variables: the atoms' lines, sorted and distinct
  std::vector<RealCell> cells;

  // Splits the box into cells (throws FractionOverflow).
  void build();
};

}  // namespace uabt::verify::detail
