// facetc --check: shaders are compiled on -j workers, and their lines are
// printed in path order as soon as every shader before them is done, so the
// output never depends on -j and a CI log still shows progress.
#include "check_mode.h"

#include "facet/support/text.h"

#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <chrono>
#include <condition_variable>
#include <ctime>
#include <filesystem>
#include <mutex>
#include <optional>
#include <set>
#include <thread>

#include "check_reports.h"
#include "output_safety.h"
#include "units.h"

namespace facet::tools {
namespace {
namespace fs = std::filesystem;

// A checked shader and what standard error shows of it.
struct Checked {
  ShaderCheck check;
  std::string shown;          // text diagnostics, coloured as --color asks
  nlohmann::json json_diags;  // with --diagnostics-format=json
  std::vector<std::string> read;  // every file the check read: the shader, its includes, UsePass and Fallback shaders
};

CheckDiagnostic resolve(const Diagnostic& d, const SourceMap& sources) {
  CheckDiagnostic out{.id = d.id, .severity = d.severity, .message = d.message};
  if (d.variant_total > 1) out.message += fmt::format(" [in {} of {} variants]", d.variant_hits, d.variant_total);
  if (d.span.has_location() && d.span.file < sources.file_count()) {
    out.file = sources.path(d.span.file);
    LineColumn begin = sources.line_column(d.span.file, d.span.begin);
    out.line = begin.line;
    out.column = begin.column;
    if (d.span.end > d.span.begin) {
      LineColumn end = sources.line_column(d.span.file, d.span.end);
      out.end_line = end.line;
      out.end_column = end.column;
    }
  }
  for (const DiagNote& note : d.notes) out.notes.push_back(note.message);
  return out;
}

// Without --materials: the variant of no keywords of every pass (as
// `--keywords ""` selects it), or every variant with --all-variants. With
// --materials: every variant the manifests' materials use.
CompileOptions check_options(const FacetcArgs& args, const StripInputs& strip, const ir::Shader& shader,
                             unsigned jobs) {
  CompileOptions options = stripped_options(compile_options(args, !strip.materials.has_value()), strip, shader);
  options.jobs = jobs;
  return options;
}

Checked check_one(const FacetcArgs& args, const Compiler& compiler, const StripInputs& strip, const std::string& path,
                  unsigned jobs) {
  auto started = std::chrono::steady_clock::now();
  Checked out;
  out.check.path = path;
  SourceMap sources;
  Diagnostics raw;
  bool compiled = false;
  // A linter over a whole project reports a shader that crashes the compiler
  // as failing rather than ending the run.
  try {
    auto shader = compiler.load(path, sources, raw, compile_options(args, false));
    if (shader) {
      auto result = compiler.compile(*shader, check_options(args, strip, *shader, jobs), sources, raw);
      if (result) {
        compiled = true;
        out.check.variants = result->stats.variants;
        out.read = result->dependencies;  // with the includes of programs the cache gave
      }
    }
  } catch (const std::exception& e) {
    raw.add(DiagId::driver_bad_option, Severity::error, {}, fmt::format("internal error: {}", e.what()));
  }
  for (FileId id = 0; id < sources.file_count(); ++id) {
    if (!sources.path(id).starts_with("<")) out.read.push_back(sources.path(id));
  }
  Diagnostics diags = apply_warning_options(raw, args.warnings);
  out.check.ok = compiled && !diags.has_errors();
  out.check.warnings = diags.warning_count();
  for (const Diagnostic& d : diags.all()) out.check.diagnostics.push_back(resolve(d, sources));
  out.check.text = render_text(diags, sources);
  if (args.diagnostics_format == DiagnosticsFormat::json) {
    out.json_diags = nlohmann::json::parse(render_json(diags, sources));
  } else {
    bool color = args.color.value_or(isatty(STDERR_FILENO) == 1);
    out.shown = color ? render_text(diags, sources, {.color = true}) : out.check.text;
  }
  out.check.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return out;
}


// "ok   path", "ok   path (2 warnings)" or "FAIL path: first error": the
// path always starts in column 6.
std::string check_line(const ShaderCheck& c) {
  if (!c.ok) {
    std::string error = first_error(c);
    return fmt::format("FAIL {}: {}\n", c.path, error.empty() ? "error: the shader does not compile" : error);
  }
  std::string detail = c.warnings > 0 ? " (" + count_of(c.warnings, "warning", "warnings") + ")" : "";
  if (c.variants == 0) detail += " (no variant selected)";
  return fmt::format("ok   {}{}\n", c.path, detail);
}

// A report path that cannot be written is found before anything compiles,
// so that a CI job misconfigured this way fails at once.
std::optional<std::string> report_path_problem(const char* kind, const std::string& path) {
  std::error_code ec;
  fs::path parent = fs::path(path).parent_path();
  if (parent.empty()) parent = ".";
  if (fs::is_directory(path, ec)) return fmt::format("cannot write the {} report '{}': it is a folder", kind, path);
  if (!fs::is_directory(parent, ec)) {
    return fmt::format("cannot write the {} report '{}': there is no folder '{}'", kind, path, parent.string());
  }
  if (::access(parent.c_str(), W_OK) != 0) {
    return fmt::format("cannot write the {} report '{}': the folder '{}' is not writable", kind, path,
                       parent.string());
  }
  return std::nullopt;
}

bool write_report(const char* kind, const std::string& path, const std::string& text, Console& console) {
  Diagnostics diags;
  if (write_file_atomically(path, text, diags)) return true;
  console.err << fmt::format("facetc: error: cannot write the {} report '{}'\n", kind, path);
  return false;
}

std::string utc_timestamp() {
  std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", &utc);
  return text;
}

// At most one thread a core (as the compiler's own -j) and one a shader.
unsigned worker_count(unsigned requested, size_t shaders) {
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  unsigned n = requested != 0 ? std::min(requested, cores) : cores;
  return unsigned(std::max<size_t>(1, std::min<size_t>(n, shaders)));
}

}  // namespace

std::string first_error(const ShaderCheck& check) {
  for (const CheckDiagnostic& d : check.diagnostics) {
    if (d.severity != Severity::error) continue;
    std::string message = d.message;
    for (char& c : message) {
      if (c == '\n' || c == '\r') c = ' ';  // one line per shader
    }
    if (d.file.empty()) return "error: " + message;
    return fmt::format("{}:{}:{}: error: {}", d.file, d.line, d.column, message);
  }
  return {};
}

int run_check(const FacetcArgs& args, const Compiler& compiler, const StripInputs& strip, Console& console,
              nlohmann::json& json_diagnostics) {
  std::vector<std::string> errors;
  std::vector<std::string> paths = find_shaders(args.inputs, errors);
  if (!args.junit_file.empty()) {
    if (auto e = report_path_problem("JUnit", args.junit_file)) errors.push_back(*e);
  }
  if (!args.sarif_file.empty()) {
    if (auto e = report_path_problem("SARIF", args.sarif_file)) errors.push_back(*e);
  }
  if (errors.empty()) {
    // Found before anything compiles, against the shaders and the materials
    // and strip files; the files the shaders read are checked once known.
    std::vector<RunInput> inputs;
    add_inputs(inputs, paths, "a shader");
    add_inputs(inputs, args.material_files, "a materials file");
    add_inputs(inputs, args.strip_files, "a strip filter");
    add_inputs(inputs, args.variant_files, "a variant collection");
    if (auto clash = output_input_clash({args.junit_file, args.sarif_file}, inputs)) errors.push_back(*clash);
  }
  if (!errors.empty()) {
    for (const std::string& e : errors) console.err << "facetc: error: " << e << "\n";
    return 1;
  }

  auto started = std::chrono::steady_clock::now();
  std::string timestamp = utc_timestamp();
  unsigned workers = worker_count(args.jobs, paths.size());
  // -j's threads are shared out: as many shaders at once as there are
  // threads (or shaders), and each gets its share for its variants, so that
  // two shaders of thousands of variants use all sixteen threads of -j16.
  unsigned threads_in_all = worker_count(args.jobs, SIZE_MAX);
  unsigned inner_jobs = std::max(1u, threads_in_all / workers);
  std::vector<std::optional<Checked>> results(paths.size());
  std::mutex mutex;
  std::condition_variable done;
  std::atomic<size_t> next{0};
  std::vector<std::thread> threads;
  for (unsigned w = 0; w < workers; ++w) {
    threads.emplace_back([&] {
      for (size_t i; (i = next++) < paths.size();) {
        Checked c = check_one(args, compiler, strip, paths[i], inner_jobs);
        std::lock_guard lock(mutex);
        results[i] = std::move(c);
        done.notify_all();
      }
    });
  }

  std::vector<ShaderCheck> checks;
  std::set<std::string> read;
  size_t passed = 0, warnings = 0;
  for (size_t i = 0; i < paths.size(); ++i) {
    Checked c;
    {
      std::unique_lock lock(mutex);
      done.wait(lock, [&] { return results[i].has_value(); });
      c = std::move(*results[i]);
      results[i].reset();
    }
    console.out << check_line(c.check);
    console.out.flush();
    if (args.diagnostics_format == DiagnosticsFormat::json) {
      for (auto& d : c.json_diags) json_diagnostics.push_back(std::move(d));
    } else {
      console.err << c.shown;
      console.err.flush();
    }
    passed += c.check.ok ? 1 : 0;
    warnings += c.check.warnings;
    checks.push_back(std::move(c.check));
    read.insert(c.read.begin(), c.read.end());
  }
  for (std::thread& t : threads) t.join();
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  console.out << fmt::format("{} of {} shaders compile; {}\n", passed, paths.size(), count_of(warnings, "warning", "warnings"));

  // The includes and the shaders a UsePass or Fallback named are known only
  // now: a report that would replace one of them is not written.
  std::vector<RunInput> read_inputs;
  add_inputs(read_inputs, {read.begin(), read.end()}, "a file a checked shader read");
  if (auto clash = output_input_clash({args.junit_file, args.sarif_file}, read_inputs)) {
    console.err << "facetc: error: " << *clash << "\n";
    return 1;
  }
  bool reports_ok = true;
  if (!args.junit_file.empty()) {
    reports_ok &= write_report("JUnit", args.junit_file, junit_xml(checks, seconds, timestamp), console);
  }
  if (!args.sarif_file.empty()) {
    std::error_code ec;
    std::string base = fs::current_path(ec).string();
    reports_ok &= write_report("SARIF", args.sarif_file, sarif_json(checks, base), console);
  }
  return passed == paths.size() && reports_ok ? 0 : 1;
}

}  // namespace facet::tools
