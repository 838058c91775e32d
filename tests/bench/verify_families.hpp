#pragma once
// The guard-verification scale families of the scale checklist, generated as real mission
// directories for `uabt verify` and `uabt gate`: a wide tree, one very long guard, and many
// real-valued guards. Each says what verify must answer, so a benchmark run or a unit test at a
// small size fails on a wrong answer.
#include <filesystem>
#include <map>
#include <string>

namespace uabt::bench {

struct VerifyFamily {
  std::filesystem::path dir;
  // Per check id, how many findings verify reports (listed ones; none when absent).
  std::map<std::string, std::size_t> findings;
};

// One adaptable node `navigation`: `hop` is a Sequence of N `<Hop distance="1"/>` actions (a
// port each, declared in nodes.xml), selected when OnDust; `hold` is the default. No findings.
VerifyFamily generate_ported_sequence(const std::filesystem::path& dir, int actions);

// The same node, `hop` selected by one guard of N disjuncts `depth = 0 | … | depth = N-1` over
// `integer depth in [0, 100000]`. No findings up to 1,000 atoms; beyond, one
// `verification-skipped` (its atoms are not checked one by one).
VerifyFamily generate_disjunct_guard(const std::filesystem::path& dir, int disjuncts);

// N alternatives selected by disjoint cells of a grid over two reals (64 columns of `wind`, as
// many rows of `battery` as needed), then a default. No findings; every share is exact.
VerifyFamily generate_real_grid(const std::filesystem::path& dir, int guards);

// The same node, `hop` selected by one guard naming N undeclared names `A0 & … & A<N-1>`, with
// no domain.fret (each name is inferred a boolean): one `ref-undeclared` warning a name, listed
// 20 times per file, and the rest counted.
VerifyFamily generate_undeclared_guard(const std::filesystem::path& dir, int names);

// The same node with `bytes` bytes of noise (a fixed pseudo-random sequence, so the same size
// writes the same file) as requirements.fret: syntax errors, listed 20 times per file.
VerifyFamily generate_noise_requirements(const std::filesystem::path& dir, int bytes);

}  // namespace uabt::bench
