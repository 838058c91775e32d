#include "bench_support.hpp"

#include <unistd.h>
#include <algorithm>
#include <map>
#include <set>
#include <tuple>

#include <z3++.h>

#include "smt/assign.hpp"
#include "smt/encoder.hpp"

namespace uabt::bench {

namespace {

class Workspace {
 public:
  Workspace() {
    root_ = std::filesystem::temp_directory_path() / ("uabt-bench-" + std::to_string(::getpid()));
    std::filesystem::create_directories(root_);
  }
  ~Workspace() {
    std::error_code ec;
    std::filesystem::remove_all(root_, ec);
  }
  const std::filesystem::path& root() const { return root_; }

 private:
  std::filesystem::path root_;
};

bool naive_sat(smt::Encoder& encoder, const std::vector<smt::Encoder::DomainPart>& parts,
               const z3::expr& formula, NaiveSolver kind, NaiveAnswers& answers) {
  z3::solver solver = kind == NaiveSolver::smt_core
                          ? z3::solver(encoder.context(), z3::solver::simple())
                          : z3::solver(encoder.context());
  for (const auto& p : parts) solver.add(p.constraint);
  solver.add(formula);
  ++answers.queries;
  return solver.check() == z3::sat;
}

}  // namespace

const std::filesystem::path& workspace() {
  static Workspace w;
  return w.root();
}

const Loaded& loaded(int nodes, int alternatives, GeneratorMode mode, int tree_nodes) {
  static std::map<std::tuple<int, int, int, int>, Loaded> cache;
  const auto key = std::make_tuple(nodes, alternatives, static_cast<int>(mode), tree_nodes);
  if (auto it = cache.find(key); it != cache.end()) return it->second;
  Loaded l;
  l.generated = generate_mission(workspace(), nodes, alternatives, mode, tree_nodes);
  if (auto m = load::load_mission(l.generated.dir, {}, l.error)) {
    l.mission = std::make_unique<load::Mission>(std::move(*m));
    if (!l.mission->findings.empty())
      l.error = "loader finding: " + l.mission->findings.front().check + ": " +
                l.mission->findings.front().message;
  }
  return cache.emplace(key, std::move(l)).first->second;
}

GeneratorMode mode_for(int nodes, int alternatives) {
  return nodes >= 3 && alternatives >= 4 ? GeneratorMode::planted : GeneratorMode::partition;
}

std::string check_findings(const std::vector<Finding>& findings,
                           const std::vector<ExpectedFinding>& expected) {
  std::multiset<std::string> want, got;
  for (const auto& e : expected) {
    std::string s = e.check + "@" + e.adaptable;
    if (e.check != "guard-gap")
      for (const auto& r : e.requirements) s += " " + r;
    want.insert(s);
  }
  for (const auto& f : findings) {
    std::string s = f.check + "@" + f.adaptable;
    if (f.check != "guard-gap") {
      auto reqs = f.requirements;
      std::sort(reqs.begin(), reqs.end());
      for (const auto& r : reqs) s += " " + r;
    }
    got.insert(s);
  }
  if (want == got) return "";
  std::string msg = "findings differ; got:";
  for (const auto& s : got) msg += " [" + s + "]";
  msg += " want:";
  for (const auto& s : want) msg += " [" + s + "]";
  return msg;
}

NaiveAnswers naive_verify(const load::Mission& mission, NaiveSolver kind) {
  NaiveAnswers answers;
  for (const auto& site : mission.adaptables) {
    smt::Encoder encoder(mission.domain);
    std::vector<Finding> findings;
    const auto parts = encoder.domain_parts(findings);
    auto& ctx = encoder.context();
    if (!naive_sat(encoder, parts, ctx.bool_val(true), kind, answers)) {
      ++answers.inconsistent;
      continue;
    }
    std::vector<z3::expr> guards;
    bool has_default = false;
    for (const auto* r : mission.selections_for(site.id)) {
      if (!r->guard) {
        has_default = true;
        continue;
      }
      auto g = encoder.lower_condition(*r->guard, r->guard_location, findings);
      if (g) guards.push_back(*g);
    }
    z3::expr higher = ctx.bool_val(false);
    for (std::size_t i = 0; i < guards.size(); ++i) {
      if (!naive_sat(encoder, parts, guards[i], kind, answers)) {
        ++answers.unsatisfiable;
      } else if (i > 0 && !naive_sat(encoder, parts, guards[i] && !higher, kind, answers)) {
        ++answers.shadowed;
      }
      smt::assign(higher, higher || guards[i]);
      for (std::size_t j = 0; j < i; ++j)
        if (naive_sat(encoder, parts, guards[j] && guards[i], kind, answers)) ++answers.overlaps;
    }
    if (!has_default && naive_sat(encoder, parts, !higher, kind, answers)) ++answers.gaps;
  }
  return answers;
}

std::string check_naive(const NaiveAnswers& answers, const std::vector<ExpectedFinding>& expected) {
  int overlaps = 0, gaps = 0, shadowed = 0;
  for (const auto& e : expected) {
    overlaps += e.check == "guard-overlap";
    gaps += e.check == "guard-gap";
    shadowed += e.check == "guard-shadowed";
  }
  if (answers.overlaps != overlaps || answers.gaps != gaps || answers.shadowed != shadowed ||
      answers.unsatisfiable || answers.inconsistent)
    return "naive baseline answers differ from the planted findings";
  return "";
}

}  // namespace uabt::bench
