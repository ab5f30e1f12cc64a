// The variant-build benchmark (issue: variants at scale). In one run, side by
// side, on a generated Standard-like uber shader (bench/uber_shader.cpp):
//   facetc cold -j1 and -j2 (no cache), cold into an empty cache, warm from it,
//   and the naive way: one glslc process per variant and stage, -D flags on
//   the same HLSL (sequential, and two at a time);
// then parse + enumerate (--list-variants) of a corpus of 300 small shaders.
// It prints seconds and ratios; only the ratios mean much on a shared machine.
//
//   facet_variant_bench --facetc build/compiler/facetc [--glslc glslc] [--work DIR]
//                       [--naive-every K]   (time every K-th variant only, and scale up)
//                       [--parallel N]      (the parallel rows use N threads / processes; default 2)
//   facet_variant_bench --facetc build/compiler/facetc --report-vs-build [--parallel N]
//                       (only: facetc --report against the cold build it describes, on the
//                        generated uber shader and stdlib/Shaders/Standard.shader;
//                        [--source-dir DIR] names the source tree holding examples/;
//                        --example-only skips the generated shader, for a slot too short for both)
#include <fmt/format.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "facet/compiler.h"
#include "uber_shader.h"

extern char** environ;

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

struct Options {
  std::string facetc, glslc = "glslc", work;
  unsigned naive_every = 1;
  unsigned parallel = 2;  // the parallel runs: facetc -jN and N glslc processes at a time
  bool report_vs_build = false;
  bool example_only = false;  // --report-vs-build on stdlib/Shaders/Standard.shader alone
  std::string source_dir = FACET_SOURCE_DIR;  // where examples/ is (another machine: --source-dir)
};

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::string quote(const std::string& s) { return "'" + s + "'"; }

// Runs a shell command; returns its wall time, or a negative value on failure.
double timed(const std::string& command) {
  auto start = Clock::now();
  int status = std::system((command + " > /dev/null 2> /dev/null").c_str());
  double t = seconds_since(start);
  return status == 0 ? t : -t;
}

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// One glslc invocation of the naive loop.
struct Job {
  std::vector<std::string> argv;
};

// Runs the jobs `parallel` at a time; false if any failed.
bool run_jobs(const std::vector<Job>& jobs, unsigned parallel) {
  std::map<pid_t, size_t> running;
  size_t next = 0;
  bool ok = true;
  while (next < jobs.size() || !running.empty()) {
    while (next < jobs.size() && running.size() < parallel) {
      std::vector<char*> argv;
      for (const std::string& a : jobs[next].argv) argv.push_back(const_cast<char*>(a.c_str()));
      argv.push_back(nullptr);
      posix_spawn_file_actions_t actions;
      posix_spawn_file_actions_init(&actions);
      posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
      pid_t pid = 0;
      if (posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ) != 0) return false;
      posix_spawn_file_actions_destroy(&actions);
      running[pid] = next++;
    }
    int status = 0;
    pid_t done = ::wait(&status);
    if (done < 0) break;
    ok = ok && WIFEXITED(status) && WEXITSTATUS(status) == 0;
    running.erase(done);
  }
  return ok;
}

struct NaivePlan {
  std::vector<Job> jobs;
  size_t all = 0;  // jobs the full loop would run
};

// The naive build: the keyword-free program text of each stage (prelude
// and includes as facet hands them to glslang), compiled once per variant
// with the variant's keywords as -D flags.
std::optional<NaivePlan> plan_naive(const Options& o, const fs::path& shader_path) {
  facet::Compiler compiler;
  const facet::backend::Backend backend;
  facet::SourceMap sources;
  facet::Diagnostics diags;
  auto shader = compiler.load(shader_path.string(), sources, diags);
  if (!shader) return std::nullopt;
  auto passes = compiler.select_passes(*shader, {}, diags);
  if (!passes) return std::nullopt;
  NaivePlan plan;
  for (const facet::SelectedPass& pass : *passes) {
    auto set = compiler.select_variants(pass, {}, diags);
    if (!set) return std::nullopt;
    const facet::ir::Program& program = *pass.ir.program;
    std::map<facet::Stage, fs::path> sources_of;
    for (facet::Stage stage : {facet::Stage::vertex, facet::Stage::fragment}) {
      auto source = backend.source_text(*shader, program, {.stage = stage, .preprocess = false}, {}, sources, diags);
      if (!source) return std::nullopt;
      fs::path file = shader_path.parent_path() / fmt::format("naive_{}.hlsl", facet::stage_name(stage));
      std::ofstream(file) << source->text;
      sources_of[stage] = file;
    }
    for (size_t k = 0; k < set->keys.size(); ++k) {
      for (facet::Stage stage : {facet::Stage::vertex, facet::Stage::fragment}) {
        ++plan.all;
        if (k % o.naive_every != 0) continue;
        Job job{{o.glslc, "-x", "hlsl", fmt::format("-fshader-stage={}", facet::stage_name(stage)),
                 "-fentry-point=" + program.entry_points[size_t(stage)], "--target-env=vulkan1.1", "-O",
                 "-I", facet::backend::default_stdlib_dir()}};
        for (const std::string& kw : facet::variants::stage_keywords(pass.keywords, set->keys[k], stage)) {
          job.argv.push_back("-D" + kw);
        }
        job.argv.push_back(sources_of[stage].string());
        job.argv.push_back("-o");
        job.argv.push_back((shader_path.parent_path() / fmt::format("naive_{}.spv", stage == facet::Stage::vertex ? "v" : "f")).string());
        plan.jobs.push_back(std::move(job));
      }
    }
  }
  return plan;
}

std::optional<Options> parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
    if (a == "--facetc") o.facetc = value();
    else if (a == "--glslc") o.glslc = value();
    else if (a == "--work") o.work = value();
    else if (a == "--naive-every") o.naive_every = unsigned(std::max(1, std::atoi(value().c_str())));
    else if (a == "--parallel") o.parallel = unsigned(std::max(2, std::atoi(value().c_str())));
    else if (a == "--report-vs-build") o.report_vs_build = true;
    else if (a == "--example-only") o.example_only = true;
    else if (a == "--source-dir") o.source_dir = value();
    else return std::nullopt;
  }
  if (o.facetc.empty()) return std::nullopt;
  if (o.work.empty()) o.work = (fs::temp_directory_path() / "facet_variant_bench").string();
  return o;
}

void row(const std::string& name, double seconds, double reference, const std::string& note = "") {
  std::cout << fmt::format("  {:<44} {:>9.2f} s {:>9.2f}x  {}\n", name, seconds, seconds / reference, note);
}

// facetc --report against a cold build of the same shader at -jN, both
// without a cache, alternating, best of `rounds` each. Returns false when
// either fails.
bool report_against_build(const Options& o, const fs::path& shader, int rounds) {
  const std::string common = quote(o.facetc) + " " + quote(shader.string()) + fmt::format(" -j{} --no-cache", o.parallel);
  const fs::path w(o.work);
  double build = 1e30, report = 1e30;
  for (int i = 0; i < rounds; ++i) {
    double b = timed(common + " -o " + quote((w / "report_bench.facetpkg").string()));
    double r = timed(common + " --report -o " + quote((w / "report_bench.txt").string()));
    if (b < 0 || r < 0) return false;
    build = std::min(build, b);
    report = std::min(report, r);
  }
  std::cout << fmt::format("  {:<44} build {:>8.2f} s  report {:>8.2f} s  report / build {:.2f}\n",
                           shader.filename().string(), build, report, report / build)
            << std::flush;
  return true;
}

int report_vs_build(const Options& o, const fs::path& uber) {
  std::cout << fmt::format("facetc --report against the cold build it describes (-j{}, no cache; best of 2, the example once)\n",
                           o.parallel);
  fs::path example = fs::path(o.source_dir) / "stdlib" / "Shaders" / "Standard.shader";
  bool ok = (o.example_only || report_against_build(o, uber, 2)) && report_against_build(o, example, 1);
  if (!ok) std::cerr << "facetc failed\n";
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  auto options = parse(argc, argv);
  if (!options) {
    std::cerr << "usage: facet_variant_bench --facetc PATH [--glslc PATH] [--work DIR] [--naive-every K]\n";
    return 2;
  }
  const Options& o = *options;
  fs::remove_all(o.work);
  fs::create_directories(o.work);
  fs::path uber = fs::path(o.work) / "StandardUber.shader";
  std::ofstream(uber) << facet::bench::uber_shader_text();
  std::string facetc = quote(o.facetc) + " " + quote(uber.string()) + " -o ";
  fs::path w(o.work);

  if (o.report_vs_build) return report_vs_build(o, uber);
  std::cout << "uber shader: " << uber << "\n";
  double cold1 = timed(facetc + quote((w / "j1.facetpkg").string()) + " -j1 --no-cache");
  const std::string jn = fmt::format(" -j{}", o.parallel);
  double cold2 = timed(facetc + quote((w / "j2.facetpkg").string()) + jn + " --no-cache");
  double cache_cold = timed(facetc + quote((w / "c.facetpkg").string()) + jn + " --cache-dir " + quote((w / "cache").string()));
  double warm = timed(facetc + quote((w / "w.facetpkg").string()) + jn + " --cache-dir " + quote((w / "cache").string()));
  if (cold1 < 0 || cold2 < 0 || cache_cold < 0 || warm < 0) {
    std::cerr << "facetc failed on the uber shader\n";
    return 1;
  }
  bool identical = read_all(w / "j1.facetpkg") == read_all(w / "j2.facetpkg") &&
                   read_all(w / "j1.facetpkg") == read_all(w / "w.facetpkg");

  auto plan = plan_naive(o, uber);
  if (!plan) {
    std::cerr << "could not plan the naive loop\n";
    return 1;
  }
  double scale = double(plan->all) / double(plan->jobs.size());
  auto start = Clock::now();
  bool naive_ok = run_jobs(plan->jobs, 1);
  double naive1 = seconds_since(start) * scale;
  start = Clock::now();
  naive_ok = run_jobs(plan->jobs, o.parallel) && naive_ok;
  double naive2 = seconds_since(start) * scale;
  if (!naive_ok) {
    std::cerr << "a glslc invocation failed\n";
    return 1;
  }

  fs::path corpus = w / "corpus";
  fs::create_directories(corpus);
  std::string list = quote(o.facetc) + " --list-variants";
  for (int i = 0; i < 300; ++i) {
    fs::path p = corpus / fmt::format("S{:03}.shader", i);
    std::ofstream(p) << facet::bench::corpus_shader_text(i);
    list += " " + quote(p.string());
  }
  double corpus_time = timed(list);

  std::string sampled = o.naive_every > 1 ? fmt::format("(every {}th variant timed, scaled x{:.1f})", o.naive_every, scale) : "";
  std::cout << fmt::format("\n{} glslc runs for the naive loop; seconds and ratio to facetc cold -j1\n", plan->all);
  row("facetc cold -j1 (no cache)", cold1, cold1);
  const unsigned n = o.parallel;
  row(fmt::format("facetc cold -j{} (no cache)", n), cold2, cold1);
  row(fmt::format("facetc cold -j{} into an empty cache", n), cache_cold, cold1);
  row(fmt::format("facetc warm -j{} from the cache", n), warm, cold1);
  row("naive glslc loop, one at a time", naive1, cold1, sampled);
  row(fmt::format("naive glslc loop, {} at a time", n), naive2, cold1, sampled);
  row("parse + enumerate 300 shaders (--list-variants)", corpus_time, cold1);
  std::cout << fmt::format("\nnaive (1 at a time) / facetc cold -j1: {:.1f}x\n", naive1 / cold1);
  std::cout << fmt::format("naive ({} at a time) / facetc cold -j{}: {:.1f}x\n", n, n, naive2 / cold2);
  std::cout << fmt::format("warm / cold (-j{}, cache): {:.1f}%\n", n, 100 * warm / cache_cold);
  std::cout << fmt::format("corpus: {:.1f} ms per shader\n", 1000 * corpus_time / 300);
  std::cout << fmt::format("packages byte-identical for -j1, -j{} and warm: {}\n", n, identical ? "yes" : "NO");
  return identical ? 0 : 1;
}
