#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "prove/explore.hpp"
#include "prove/model.hpp"
#include "prove/prove.hpp"

namespace uabt::prove {

// How far the symbolic engine goes when no --depth is given: BMC to this many ticks and
// k-induction up to this k.
inline constexpr std::uint64_t kSymbolicBound = 40;
// k-induction runs alone up to this k; IC3/PDR (Spacer) then tries what is still open. What
// 2-induction leaves open, deeper induction rarely proves, and each depth costs about twice the
// one before while Spacer takes a second or two (measured: lunar and msl_curiosity 3-4x faster
// with 2 than with 6, the same verdicts and violation ticks; BMC goes on for what stays open).
inline constexpr std::uint64_t kInductionBeforePdr = 2;
// IC3/PDR is first asked with this many frames, all open guarantees in one query: it proves
// msl_curiosity's and lunar's within 3, in a fraction of the time of the full search per
// guarantee.
inline constexpr unsigned kPdrFirstLevels = 3;
// What that leaves open BMC checks to this depth before IC3/PDR searches with all its frames:
// IC3/PDR takes seconds to find a violation BMC finds in a fraction of that (checklist 10,
// violated at tick 11: 4 s of IC3/PDR and 4 s of induction before).
inline constexpr std::uint64_t kBmcBeforePdr = 12;
// The frames IC3/PDR may open per guarantee before it gives up (deterministic, unlike a
// timeout).
inline constexpr unsigned kPdrMaxLevel = 64;

struct SymbolicSearch {
  std::vector<std::optional<Finding>> violations;  // per property (guarantees only)
  std::vector<std::uint64_t> proved_k;  // per property: the k whose induction proved it, else 0
  std::vector<bool> proved;
  std::vector<bool> by_pdr;  // per property: proved by IC3/PDR rather than k-induction
  std::uint64_t depth = 0;   // BMC depth checked (no violation of the open guarantees below it)
  std::uint64_t induction_k = 0;       // deepest induction tried
  std::uint64_t bmc_checks = 0;        // satisfiability checks of BMC
  std::uint64_t induction_checks = 0;  // satisfiability checks of k-induction
  std::uint64_t pdr_queries = 0;       // IC3/PDR queries
  // No first tick satisfies world.json's initial and the assumptions: every "proof" would be
  // vacuous.
  bool no_first_tick = false;
  // A run still going after this tick cannot take another (a deadlock: the assumptions leave
  // the environment no value); 0 when none.
  std::uint64_t deadlock_after = 0;
  // Per property: the first tick at which its trigger (its mode and its condition) holds on
  // some run (BMC: the shortest), 0 when no run reaches it; decided when either is known
  // (a guarantee without a trigger, or one violated, is not asked).
  std::vector<std::uint64_t> first_trigger;
  std::vector<bool> trigger_decided;
  // One of the shortest runs whose last tick stops with an error (Finding::property is not
  // used); error_decided when that, or that no tick does, is known.
  std::optional<Finding> error;
  bool error_decided = true;
  // Why the search stopped before its bound with guarantees open ("" when it did not): the
  // resource budget spent, or a check Z3 could not decide.
  std::string stopped_early;
};

// BMC with increasing depth (a violation is found at its shortest tick) and k-induction with
// all states of the path distinct (proves a guarantee for every depth), then IC3/PDR, over
// SymbolicTick. The same search finds the first tick that stops with an error and the first
// tick each guarantee's trigger holds, or proves that none does.
// Throws SymbolicUnsupported when the mission is outside what SymbolicTick models.
SymbolicSearch symbolic_search(Model& model, const Options& options);

}  // namespace uabt::prove
