// uabt_bench: Google Benchmark over the stages, plus three command-line modes that give the
// issue's figures without Google Benchmark's repetition:
//
//   uabt_bench [--benchmark_* flags]                  the benchmarks (bench_*.cpp)
//   uabt_bench generate N K DIR [--planted] [--tree-nodes M]
//                                                     write a synthetic mission to DIR
//   uabt_bench measure N K [--threads T] [--naive default|core]
//                                                     one size: times, queries, peak memory
//   uabt_bench scale [--quick]                        the scaling curves (Markdown), each
//                                                     point measured in a process of its own
//   uabt_bench process RUNS COMMAND [ARGS…]           a whole command RUNS times: wall time
//                                                     (min, median, max), CPU, peak memory
//   uabt_bench selection                              --selection optimized against Fig. 4:
//                                                     condition ticks per selection, compile time
//   uabt_bench prove-family FAMILY SIZE DIR [--counters V]
//                                                     write a mission of a model-checking
//                                                     family (prove_families.hpp) to DIR:
//                                                     binary, checklist, preflight, recheck,
//                                                     recheck_kept, wide_disjuncts, wide_enum,
//                                                     lunar, lunar_reserve (the last two: size 1)
//   uabt_bench verify-family FAMILY SIZE DIR         the same for a guard-check family
//                                                     (verify_families.hpp): ported, disjuncts,
//                                                     reals, undeclared, noise
#include <benchmark/benchmark.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bench_selection.hpp"
#include "bench_support.hpp"
#include "gate/gate.hpp"
#include "prove_families.hpp"
#include "smt/solver.hpp"
#include "verify/verify.hpp"
#include "verify_families.hpp"

extern char** environ;

namespace {

using namespace uabt::bench;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

int usage() {
  std::fprintf(
      stderr,
      "usage: uabt_bench [--benchmark_* flags]\n"
      "       uabt_bench generate N K DIR [--planted] [--tree-nodes M]\n"
      "       uabt_bench measure N K [--threads T] [--naive default|core]\n"
      "       uabt_bench scale [--quick]\n"
      "       uabt_bench process RUNS COMMAND [ARGS...]\n"
      "       uabt_bench selection\n"
      "       uabt_bench prove-family binary|checklist|preflight|recheck|recheck_kept|"
      "wide_disjuncts|wide_enum|lunar|lunar_reserve SIZE DIR [--counters V]\n"
      "       uabt_bench verify-family ported|disjuncts|reals|undeclared|noise SIZE DIR\n");
  return 2;
}

std::optional<int> positive(const char* text) {
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || v < 1 || v > 1'000'000) return std::nullopt;
  return static_cast<int>(v);
}

// Prints the compiled tree's node count and the expected verdicts (a violated one with its
// tick: `BelowMax=violated@8`), for prove_families.sh.
int prove_family(int argc, char** argv) {
  if (argc != 5 && argc != 7) return usage();
  const std::string family = argv[2];
  const auto size = positive(argv[3]);
  int counters = 3;
  if (argc == 7) {
    const auto v = positive(argv[6]);
    if (std::string(argv[5]) != "--counters" || !v) return usage();
    counters = *v;
  }
  if (!size || ((family == "lunar" || family == "lunar_reserve") && *size != 1)) return usage();
  FamilyMission m;
  if (family == "binary")
    m = generate_binary_tree(argv[4], *size, counters);
  else if (family == "checklist")
    m = generate_checklist(argv[4], *size);
  else if (family == "preflight")
    m = generate_preflight(argv[4], *size);
  else if (family == "recheck" || family == "recheck_kept")
    m = generate_recheck(argv[4], *size, family == "recheck_kept");
  else if (family == "wide_disjuncts")
    m = generate_disjunct_site(argv[4], *size);
  else if (family == "wide_enum")
    m = generate_enum_site(argv[4], *size);
  else if (family == "lunar")
    m = generate_lunar(argv[4]);
  else if (family == "lunar_reserve")
    m = generate_lunar_reserve(argv[4]);
  else
    return usage();
  std::printf("%d", m.tree_nodes);
  for (const auto& [id, verdict] : m.verdicts) {
    std::printf(" %s=%s", id.c_str(), verdict.c_str());
    if (const auto tick = m.violation_ticks.find(id); tick != m.violation_ticks.end())
      std::printf("@%llu", static_cast<unsigned long long>(tick->second));
  }
  std::printf("\n");
  return 0;
}

// Prints the findings verify must report, per check (`verification-skipped=1`).
int verify_family(int argc, char** argv) {
  if (argc != 5) return usage();
  const std::string family = argv[2];
  const char* text = argv[3];
  char* end = nullptr;
  const long size = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || size < 1 || size > 100'000'000) return usage();
  const int n = static_cast<int>(size);
  VerifyFamily f;
  if (family == "ported")
    f = generate_ported_sequence(argv[4], n);
  else if (family == "disjuncts")
    f = generate_disjunct_guard(argv[4], n);
  else if (family == "reals")
    f = generate_real_grid(argv[4], n);
  else if (family == "undeclared")
    f = generate_undeclared_guard(argv[4], n);
  else if (family == "noise")
    f = generate_noise_requirements(argv[4], n);
  else
    return usage();
  for (const auto& [check, count] : f.findings) std::printf("%s=%zu ", check.c_str(), count);
  std::printf("\n");
  return 0;
}

int generate(int argc, char** argv) {
  if (argc < 5) return usage();
  const auto n = positive(argv[2]), k = positive(argv[3]);
  if (!n || !k) return usage();
  GeneratorMode mode = GeneratorMode::partition;
  int tree_nodes = 1;
  for (int a = 5; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--planted") {
      mode = GeneratorMode::planted;
    } else if (arg == "--tree-nodes" && a + 1 < argc && positive(argv[a + 1])) {
      tree_nodes = *positive(argv[++a]);
    } else {
      return usage();
    }
  }
  const std::filesystem::path parent = argv[4];
  std::filesystem::create_directories(parent);
  const GeneratedMission m = generate_mission(parent, *n, *k, mode, tree_nodes);
  std::printf("%s\n", m.dir.string().c_str());
  for (const auto& e : m.expected)
    std::printf("expected: %s at %s\n", e.check.c_str(), e.adaptable.c_str());
  return 0;
}

// One line: N K threads verify_ms gate_ms queries prefiltered naive_ms peak_MiB answers.
int measure(int argc, char** argv) {
  if (argc < 4) return usage();
  const auto n = positive(argv[2]), k = positive(argv[3]);
  if (!n || !k) return usage();
  unsigned threads = 0;
  std::optional<NaiveSolver> naive;
  for (int a = 4; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--threads" && a + 1 < argc && positive(argv[a + 1])) {
      threads = static_cast<unsigned>(*positive(argv[++a]));
    } else if (arg == "--naive" && a + 1 < argc) {
      const std::string kind = argv[++a];
      if (kind != "default" && kind != "core") return usage();
      naive = kind == "core" ? NaiveSolver::smt_core : NaiveSolver::default_strategy;
    } else {
      return usage();
    }
  }
  const Loaded& l = loaded(*n, *k, mode_for(*n, *k));
  if (!l.mission || !l.error.empty()) {
    std::fprintf(stderr, "uabt_bench: %s\n", l.error.c_str());
    return 1;
  }
  uabt::verify::Options options;
  options.threads = threads;
  auto start = Clock::now();
  const uabt::verify::Result result = uabt::verify::verify_mission(*l.mission, options);
  const double verify_ms = ms_since(start);
  std::string answers = check_findings(result.findings, l.generated.expected);

  start = Clock::now();
  std::string error;
  auto mission = uabt::load::load_mission(l.generated.dir, {}, error);
  uabt::gate::Options gate_options;
  gate_options.verify.threads = threads;
  const auto outcome = uabt::gate::run_gate(std::move(*mission), gate_options, "bench");
  const double gate_ms = ms_since(start);
  if (answers.empty() && l.generated.expected.empty() && !outcome.passed())
    answers = "the gate failed a partition";

  double naive_ms = 0;
  if (naive) {
    start = Clock::now();
    const NaiveAnswers naive_answers = naive_verify(*l.mission, *naive);
    naive_ms = ms_since(start);
    if (answers.empty()) answers = check_naive(naive_answers, l.generated.expected);
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("%d %d %u %.1f %.1f %llu %llu %.1f %.1f %s\n", *n, *k, threads, verify_ms, gate_ms,
              static_cast<unsigned long long>(result.statistics.solver_queries),
              static_cast<unsigned long long>(result.statistics.prefiltered), naive_ms,
              static_cast<double>(usage.ru_maxrss) / 1024.0, answers.empty() ? "ok" : "WRONG");
  if (!answers.empty()) std::fprintf(stderr, "uabt_bench: %s\n", answers.c_str());
  return answers.empty() ? 0 : 1;
}

// Runs `uabt_bench measure …` in a child process and returns its line.
std::optional<std::string> measure_in_child(const std::vector<std::string>& args) {
  std::vector<std::string> all{"/proc/self/exe", "measure"};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  int fds[2];
  if (pipe(fds) != 0) return std::nullopt;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, "/proc/self/exe", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(fds[1]);
  std::string out;
  char buffer[512];
  for (ssize_t got; spawned == 0 && (got = read(fds[0], buffer, sizeof buffer)) > 0;)
    out.append(buffer, static_cast<std::size_t>(got));
  close(fds[0]);
  int status = 0;
  if (spawned != 0 || waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) ||
      WEXITSTATUS(status) != 0)
    return std::nullopt;
  while (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

struct Point {
  int n = 0, k = 0;
  unsigned threads = 0;
  double verify_ms = 0, gate_ms = 0, naive_ms = 0, peak_mib = 0;
  unsigned long long queries = 0, prefiltered = 0;
};

std::optional<Point> parse_point(const std::string& line) {
  Point p;
  char answers[16] = {};
  if (std::sscanf(line.c_str(), "%d %d %u %lf %lf %llu %llu %lf %lf %15s", &p.n, &p.k, &p.threads,
                  &p.verify_ms, &p.gate_ms, &p.queries, &p.prefiltered, &p.naive_ms, &p.peak_mib,
                  answers) != 10 ||
      std::string(answers) != "ok")
    return std::nullopt;
  return p;
}

int scale(int argc, char** argv) {
  bool quick = false;
  for (int a = 2; a < argc; ++a) {
    if (std::string(argv[a]) == "--quick")
      quick = true;
    else
      return usage();
  }
  struct Size {
    int n, k;
    const char* naive;  // nullptr: too slow to run naively
  };
  const std::vector<Size> by_k =
      quick ? std::vector<Size>{{1, 8, "core"}, {1, 32, "core"}, {1, 128, nullptr}}
            : std::vector<Size>{{1, 8, "core"},
                                {1, 32, "core"},
                                {1, 128, "core"},
                                {1, 512, nullptr},
                                {1, 2048, nullptr}};
  const std::vector<Size> by_n =
      quick ? std::vector<Size>{{3, 32, "core"}, {10, 32, nullptr}}
            : std::vector<Size>{
                  {3, 32, "core"}, {10, 32, "core"}, {30, 32, nullptr}, {100, 32, nullptr}};
  bool ok = true;
  auto table = [&](const char* title, const std::vector<Size>& sizes) {
    std::printf("\n%s\n\n", title);
    std::printf(
        "| N | K | verify ms | gate ms | solver queries | prefiltered | naive ms "
        "| naive / verify | peak MiB |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const auto& s : sizes) {
      std::vector<std::string> args{std::to_string(s.n), std::to_string(s.k)};
      if (s.naive) args.insert(args.end(), {"--naive", s.naive});
      const auto line = measure_in_child(args);
      const auto p = line ? parse_point(*line) : std::nullopt;
      if (!p) {
        std::printf("| %d | %d | failed | | | | | | |\n", s.n, s.k);
        ok = false;
        continue;
      }
      std::string naive = "-", ratio = "-";
      if (s.naive) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.1f", p->naive_ms);
        naive = buf;
        std::snprintf(buf, sizeof buf, "%.0fx", p->naive_ms / p->verify_ms);
        ratio = buf;
      }
      std::printf("| %d | %d | %.1f | %.1f | %llu | %llu | %s | %s | %.1f |\n", p->n, p->k,
                  p->verify_ms, p->gate_ms, p->queries, p->prefiltered, naive.c_str(),
                  ratio.c_str(), p->peak_mib);
      std::fflush(stdout);
    }
  };
  table("Time against K (one adaptable node)", by_k);
  table("Time against N (32 alternatives each)", by_n);
  return ok ? 0 : 1;
}

// Runs a command RUNS times (its output discarded) and reports wall time, CPU time and peak
// resident memory, as /usr/bin/time -v would for each run.
int process(int argc, char** argv) {
  if (argc < 4) return usage();
  const auto runs = positive(argv[2]);
  if (!runs) return usage();
  std::vector<double> wall;
  double cpu_ms = 0, peak_mib = 0;
  int exit_code = 0;
  for (int r = 0; r < *runs; ++r) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    const auto start = Clock::now();
    const int spawned = posix_spawnp(&pid, argv[3], &actions, nullptr, argv + 3, environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) {
      std::fprintf(stderr, "uabt_bench: cannot run %s\n", argv[3]);
      return 1;
    }
    int status = 0;
    rusage usage{};
    if (wait4(pid, &status, 0, &usage) < 0) return 1;
    wall.push_back(ms_since(start));
    cpu_ms += (usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) * 1e3 +
              (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e3;
    peak_mib = std::max(peak_mib, static_cast<double>(usage.ru_maxrss) / 1024.0);
    exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128;
  }
  std::sort(wall.begin(), wall.end());
  std::printf(
      "%d runs, exit status %d: wall min %.1f ms, median %.1f ms, max %.1f ms; CPU %.1f ms "
      "per run; peak RSS %.1f MiB\n",
      *runs, exit_code, wall.front(), wall[wall.size() / 2], wall.back(), cpu_ms / *runs, peak_mib);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  uabt::smt::keep_freed_memory();  // as the uabt command does
  if (argc >= 2) {
    const std::string mode = argv[1];
    try {
      if (mode == "generate") return generate(argc, argv);
      if (mode == "measure") return measure(argc, argv);
      if (mode == "scale") return scale(argc, argv);
      if (mode == "process") return process(argc, argv);
      if (mode == "selection") return uabt::bench::selection_figures();
      if (mode == "prove-family") return prove_family(argc, argv);
      if (mode == "verify-family") return verify_family(argc, argv);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "uabt_bench: %s\n", e.what());
      return 1;
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return usage();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
