// Translation validation of a compiled tree against its mission (ARCHITECTURE §6).
#include "conform/conform.hpp"

#include <set>

#include "conform/context.hpp"
#include "conform/equivalence.hpp"
#include "conform/selection.hpp"
#include "conform/tree_rules.hpp"

namespace uabt::conform {

Result conform_tree(const load::Mission& mission, const bt::Document& compiled,
                    const Options& options) {
  Context ctx(mission, compiled);
  check_adaptables_left(ctx);
  check_dangling_subtrees(ctx);
  check_compiled_structure(ctx);
  check_fixed_part(ctx);

  Prover prover(mission.domain, options.timeout_ms);
  std::set<std::string> adaptables_done;
  std::set<std::string> alternatives_done;
  for (const auto& site : mission.adaptables) {
    if (site.id.empty() || !adaptables_done.insert(site.id).second) continue;
    check_selection(ctx, prover, site.id, alternatives_done);
  }

  Result result;
  result.findings = std::move(ctx.findings());
  result.solver_queries = prover.queries();
  sort_findings(result.findings);
  return result;
}

}  // namespace uabt::conform
