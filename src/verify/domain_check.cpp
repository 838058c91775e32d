#include "verify/domain_check.hpp"

namespace uabt::verify::detail {

namespace {

std::string where(const SourceLocation& l) {
  if (l.file.empty()) return "";
  // Appended piece by piece: GCC 12 at -O3 warns (-Wrestrict) on the one-expression form.
  std::string out = " (";
  out += l.file;
  if (l.line > 0) {
    out += ':';
    out += std::to_string(l.line);
  }
  out += ')';
  return out;
}

}  // namespace

bool domain_known(const fretish::Domain& domain) {
  for (const auto& v : domain.variables)
    if (!v.invalid.empty()) return false;
  return true;
}

Answer check_domain(Session& session, const std::vector<smt::Encoder::DomainPart>& parts,
                    std::vector<Finding>& findings) {
  if (parts.empty()) {  // no ranges, no enums, no assumptions: every assignment is a state
    ++session.statistics().prefiltered;
    return Answer::sat;
  }
  // Each part behind its own literal, so an unsat core names the parts that clash.
  std::vector<z3::expr> literals;
  for (const auto& p : parts) literals.push_back(session.guard(p.constraint, "domain"));
  const Answer answer = session.check(literals);
  if (answer == Answer::sat) {
    for (const auto& l : literals) session.add(l);
    return answer;
  }
  SourceLocation location = parts.front().location;
  if (answer == Answer::unknown) {
    Finding f = make_finding("verification-inconclusive",
                             "could not decide whether the domain is consistent: Z3 answered "
                             "unknown (" +
                                 session.reason_unknown() + ")",
                             location);
    f.notes.push_back("no guard is checked against a domain that may be empty");
    findings.push_back(std::move(f));
    return answer;
  }
  std::vector<z3::expr> core_literals;
  for (const auto& c : session.core()) core_literals.push_back(c);
  core_literals = session.minimise({}, core_literals);
  std::vector<const smt::Encoder::DomainPart*> clash;
  for (std::size_t k = 0; k < parts.size(); ++k)
    for (const auto& c : core_literals)
      if (z3::eq(c, literals[k])) clash.push_back(&parts[k]);
  std::string names;
  for (std::size_t k = 0; k < clash.size(); ++k)
    names += (k == 0 ? "" : k + 1 == clash.size() ? " and " : ", ") + clash[k]->description;
  // Point at the last assumption of the clash (a declaration when none is involved).
  const smt::Encoder::DomainPart* at = clash.empty() ? &parts.front() : clash.back();
  for (const auto* p : clash)
    if (p->description.starts_with("assumption")) at = p;
  location = at->location;
  Finding f = make_finding("domain-inconsistent",
                           "the domain is inconsistent: no state satisfies " +
                               (names.empty() ? std::string("its declarations") : names) +
                               (clash.size() > 1 ? " together" : ""),
                           location);
  for (const auto* p : clash) f.notes.push_back(p->description + where(p->location));
  f.notes.push_back("every guard check would hold vacuously, so none is made");
  findings.push_back(std::move(f));
  return answer;
}

}  // namespace uabt::verify::detail
