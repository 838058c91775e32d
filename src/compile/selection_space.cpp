// Cuts a selection's state space into cells on which every atom is constant.
#include "compile/selection_space.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include "base/number_text.hpp"
#include "compile/guard_rewrite.hpp"
#include "fretish/relation.hpp"

namespace uabt::compile {

using fretish::Expr;
using fretish::ExprKind;

namespace {

// A decimal literal a double holds exactly enough to order the cuts: at most 15 digits.
std::optional<double> parse_number(const std::string& text) {
  if (text.empty() || std::count_if(text.begin(), text.end(), ::isdigit) > 15) return std::nullopt;
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used != text.size() || !std::isfinite(v)) return std::nullopt;
    return v;
  } catch (...) {
    return std::nullopt;
  }
}

// A number literal, or the negation of one, with its text.
std::optional<std::pair<double, std::string>> constant_of(const Expr& e) {
  if (e.kind == ExprKind::number) {
    if (auto v = parse_number(e.text)) return std::make_pair(*v, e.text);
  } else if (e.kind == ExprKind::negate && e.args.size() == 1 &&
             e.args[0]->kind == ExprKind::number) {
    if (auto v = parse_number(e.args[0]->text)) return std::make_pair(-*v, "-" + e.args[0]->text);
  }
  return std::nullopt;
}

bool compare(double x, ExprKind op, double c) {
  switch (op) {
    case ExprKind::eq: return x == c;
    case ExprKind::ne: return x != c;
    case ExprKind::lt: return x < c;
    case ExprKind::le: return x <= c;
    case ExprKind::gt: return x > c;
    default: return x >= c;
  }
}

// What one atom is, before the dimensions exist.
struct Atom {
  Dimension::Kind kind = Dimension::Kind::opaque;
  std::string variable;  // boolean, ordered, enumeration
  ExprKind op = ExprKind::eq;
  double constant = 0;
  std::string constant_text;  // ordered: the number; enumeration: the literal
  fretish::ExprPtr expr;
};

Atom classify(const fretish::ExprPtr& e, const fretish::Domain& domain) {
  Atom a;
  a.expr = e;
  if (e->kind == ExprKind::identifier && is_boolean_valued(*e, domain)) {
    a.kind = Dimension::Kind::boolean;
    a.variable = e->text;
    return a;
  }
  if (!fretish::is_relation(e->kind) || e->args.size() != 2) return a;
  for (int side = 0; side < 2; ++side) {
    const Expr& var = *e->args[side];
    const Expr& other = *e->args[1 - side];
    if (var.kind != ExprKind::identifier) continue;
    const fretish::Variable* v = domain.find(var.text);
    if (v == nullptr) continue;
    if (v->type == fretish::VarType::integer || v->type == fretish::VarType::real) {
      auto c = constant_of(other);
      if (!c) continue;
      a.kind = Dimension::Kind::ordered;
      a.variable = v->name;
      a.op = side == 0 ? e->kind : fretish::mirrored_relation(e->kind);
      a.constant = c->first;
      a.constant_text = c->second;
      return a;
    }
    if (v->type == fretish::VarType::enumeration &&
        (e->kind == ExprKind::eq || e->kind == ExprKind::ne) &&
        other.kind == ExprKind::identifier && domain.find(other.text) == nullptr &&
        std::find(v->enum_values.begin(), v->enum_values.end(), other.text) !=
            v->enum_values.end()) {
      a.kind = Dimension::Kind::enumeration;
      a.variable = v->name;
      a.op = e->kind;
      a.constant_text = other.text;
      return a;
    }
  }
  return a;
}

std::string dimension_key(const Atom& a) {
  return a.kind == Dimension::Kind::opaque ? "?" + fretish::to_fretish(*a.expr) : a.variable;
}

double representative(const Dimension::Piece& p) {
  if (p.point) return p.at;
  if (p.open_below) return p.above - 1;
  if (p.open_above) return p.below + 1;
  return p.below + (p.above - p.below) / 2;
}

double integers_between(double below, double above) {  // in the open interval
  const double first = std::floor(below) + 1, last = std::ceil(above) - 1;
  return last >= first ? last - first + 1 : 0;
}

void ordered_pieces(Dimension& dim, const fretish::Variable& v,
                    std::map<double, std::string> cuts) {
  const auto lo = parse_number(v.lower), hi = parse_number(v.upper);
  if (lo) cuts.emplace(*lo, v.lower);
  if (hi) cuts.emplace(*hi, v.upper);
  std::vector<std::pair<double, std::string>> kept;
  for (const auto& [value, text] : cuts)
    if ((!lo || value >= *lo) && (!hi || value <= *hi)) kept.emplace_back(value, text);
  dim.integer = v.type == fretish::VarType::integer;
  auto add = [&](Dimension::Piece p) {
    if (dim.integer && p.point) p.weight = std::floor(p.at) == p.at ? 1 : 0;
    if (dim.integer && !p.point)
      p.weight = p.open_below || p.open_above ? 1 : integers_between(p.below, p.above);
    if (!dim.integer)
      p.weight = p.point ? 0 : (p.open_below || p.open_above ? 1 : p.above - p.below);
    if (dim.integer && p.weight == 0) return;  // no state lies there
    dim.pieces.push_back(std::move(p));
  };
  if (!lo && !kept.empty()) {
    Dimension::Piece p;
    p.open_below = true;
    p.above = kept.front().first;
    p.text = kept.front().second;
    add(p);
  }
  for (std::size_t i = 0; i < kept.size(); ++i) {
    Dimension::Piece point;
    point.point = true;
    point.at = kept[i].first;
    point.text = kept[i].second;
    add(point);
    if (i + 1 < kept.size()) {
      Dimension::Piece open;
      open.below = kept[i].first;
      open.above = kept[i + 1].first;
      open.text = kept[i + 1].second;
      add(open);
    }
  }
  if (!hi && !kept.empty()) {
    Dimension::Piece p;
    p.open_above = true;
    p.below = kept.back().first;
    add(p);
  }
}

void truth_pieces(Dimension& dim) {
  for (int b = 0; b < 2; ++b) {
    Dimension::Piece p;
    p.weight = 1;
    p.text = b ? "true" : "false";
    dim.pieces.push_back(p);
  }
}

class Builder {
 public:
  explicit Builder(const fretish::Domain& domain) : domain_(domain) {}

  // Rewrites a condition as Algorithm 1 does and collects its atoms.
  CellExpr lower(const Expr& e) {
    CellExpr out;
    switch (e.kind) {
      case ExprKind::bool_literal:
        out.op = CellExpr::Op::constant;
        out.value = e.bool_value;
        return out;
      case ExprKind::logical_not:
      case ExprKind::logical_and:
      case ExprKind::logical_or:
        out.op = e.kind == ExprKind::logical_not   ? CellExpr::Op::negation
                 : e.kind == ExprKind::logical_and ? CellExpr::Op::conjunction
                                                   : CellExpr::Op::disjunction;
        for (const auto& a : e.args) out.args.push_back(lower(*a));
        return out;
      default: break;
    }
    const std::string text = fretish::to_fretish(e);
    auto it = atom_index_.find(text);
    if (it == atom_index_.end()) {
      it = atom_index_.emplace(text, atoms_.size()).first;
      atoms_.push_back(classify(std::make_shared<Expr>(e), domain_));
    }
    out.op = CellExpr::Op::atom;
    out.atom = it->second;
    return out;
  }

  void finish(SelectionSpace& space) {
    std::map<std::string, std::size_t> dim_index;
    std::map<std::string, std::map<double, std::string>> cuts;
    for (const Atom& a : atoms_) {
      const std::string key = dimension_key(a);
      if (a.kind == Dimension::Kind::ordered) cuts[key].emplace(a.constant, a.constant_text);
      if (dim_index.count(key)) continue;
      dim_index.emplace(key, space.dimensions.size());
      Dimension d;
      d.kind = a.kind;
      d.name = a.kind == Dimension::Kind::opaque ? fretish::to_fretish(*a.expr) : a.variable;
      if (a.kind == Dimension::Kind::opaque) d.atom = a.expr;
      space.dimensions.push_back(std::move(d));
    }
    for (Dimension& d : space.dimensions) {
      if (d.kind == Dimension::Kind::ordered) {
        ordered_pieces(d, *domain_.find(d.name), cuts[d.name]);
      } else if (d.kind == Dimension::Kind::enumeration) {
        for (const auto& lit : domain_.find(d.name)->enum_values) {
          Dimension::Piece p;
          p.weight = 1;
          p.text = lit;
          d.pieces.push_back(p);
        }
      } else {
        truth_pieces(d);
      }
    }
    for (const Atom& a : atoms_) {
      AtomTruth t;
      t.dimension = dim_index.at(dimension_key(a));
      const Dimension& d = space.dimensions[t.dimension];
      for (const auto& p : d.pieces) {
        bool h = false;
        switch (a.kind) {
          case Dimension::Kind::ordered: h = compare(representative(p), a.op, a.constant); break;
          case Dimension::Kind::enumeration:
            h = (p.text == a.constant_text) == (a.op == ExprKind::eq);
            break;
          default: h = p.text == "true"; break;
        }
        t.holds.push_back(h);
      }
      space.atoms.push_back(std::move(t));
    }
  }

 private:
  const fretish::Domain& domain_;
  std::vector<Atom> atoms_;
  std::map<std::string, std::size_t> atom_index_;
};

}  // namespace

bool evaluate_on_cell(const SelectionSpace& space, const CellExpr& e, std::size_t cell,
                      int* ticked) {
  switch (e.op) {
    case CellExpr::Op::constant: return e.value;
    case CellExpr::Op::atom:
      if (ticked) ++*ticked;
      return space.atom_holds(e.atom, cell);
    case CellExpr::Op::negation: return !evaluate_on_cell(space, e.args.at(0), cell, ticked);
    case CellExpr::Op::conjunction:
      for (const auto& a : e.args)
        if (!evaluate_on_cell(space, a, cell, ticked)) return false;
      return true;
    case CellExpr::Op::disjunction:
      for (const auto& a : e.args)
        if (evaluate_on_cell(space, a, cell, ticked)) return true;
      return false;
  }
  return false;
}

std::optional<State> cell_state(const SelectionSpace& space, std::size_t cell) {
  State state;
  for (std::size_t d = 0; d < space.dimensions.size(); ++d) {
    const Dimension& dim = space.dimensions[d];
    const Dimension::Piece& p = dim.pieces[space.piece(cell, d)];
    switch (dim.kind) {
      case Dimension::Kind::opaque: return std::nullopt;
      case Dimension::Kind::boolean:
        state.emplace_back(dim.name, Value::of_bool(p.text == "true"));
        break;
      case Dimension::Kind::enumeration:
        state.emplace_back(dim.name, Value::of_enum(p.text));
        break;
      case Dimension::Kind::ordered: {
        if (dim.integer) {
          const double v = p.point        ? p.at
                           : p.open_below ? std::ceil(p.above) - 1
                                          : std::floor(p.below) + 1;
          state.emplace_back(dim.name, Value::of_int(static_cast<std::int64_t>(v)));
        } else {
          const double v = representative(p);
          state.emplace_back(dim.name, Value::of_real(v, p.point ? p.text : number_text(v)));
        }
        break;
      }
    }
  }
  return state;
}

std::optional<SelectionSpace> build_selection_space(const std::vector<fretish::ExprPtr>& guards,
                                                    const fretish::Domain& domain,
                                                    std::size_t max_cells) {
  SelectionSpace space;
  Builder builder(domain);
  for (const auto& g : guards) {
    if (g == nullptr) {
      CellExpr always;
      always.value = true;
      space.guards.push_back(always);
    } else {
      space.guards.push_back(builder.lower(*to_and_or_not(*g, domain)));
    }
  }
  std::vector<CellExpr> assumptions;
  for (const auto& a : domain.assumptions)
    if (a.expr) assumptions.push_back(builder.lower(*to_and_or_not(*a.expr, domain)));
  builder.finish(space);

  const std::size_t dims = space.dimensions.size();
  double total = 1;
  for (const auto& d : space.dimensions) {
    total *= static_cast<double>(d.pieces.size());
    if (d.pieces.empty() || total > static_cast<double>(max_cells)) return std::nullopt;
  }
  std::vector<std::uint32_t> at(dims, 0);
  for (;;) {
    const std::size_t cell = space.weight.size();
    space.pieces.insert(space.pieces.end(), at.begin(), at.end());
    space.weight.push_back(0);  // placeholder while the cell is judged
    bool valid = true;
    for (const auto& a : assumptions)
      if (!evaluate_on_cell(space, a, cell)) valid = false;
    if (valid) {
      double w = 1;
      for (std::size_t d = 0; d < dims; ++d) w *= space.dimensions[d].pieces[at[d]].weight;
      space.weight.back() = w;
      int label = -1;
      for (std::size_t r = 0; r < space.guards.size() && label < 0; ++r)
        if (evaluate_on_cell(space, space.guards[r], cell)) label = static_cast<int>(r);
      space.label.push_back(label);
    } else {
      space.pieces.resize(space.pieces.size() - dims);
      space.weight.pop_back();
    }
    std::size_t d = 0;
    while (d < dims && ++at[d] == space.dimensions[d].pieces.size()) at[d++] = 0;
    if (d == dims) break;
  }
  return space;
}

}  // namespace uabt::compile
