// The #include resolver handed to glslang. Searches, for `#include "x"`,
// the including file's folder, then BackendOptions::include_dirs, then the
// stdlib; for `#include <x>` the last two. When BackendOptions::resolver is
// set it replaces the file system for the first two steps; the stdlib folder
// is still searched on disk when the resolver finds nothing.
#pragma once

#ifndef ENABLE_HLSL
#define ENABLE_HLSL 1  // glslang's HLSL API (setHlslIoMapping, ...); the library is built with it
#endif
#include <glslang/Public/ShaderLang.h>

#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "include_scan.h"
#include "macro_budget.h"
#include "source_assembly.h"
#include "facet/backend.h"

namespace facet::backend {

// glslang has no depth limit of its own; a file that includes itself without
// a guard would otherwise recurse until the stack runs out.
inline constexpr size_t kMaxIncludeDepth = 64;

// One successful #include, in the order glslang asked for them.
struct IncludeRecord {
  std::string path;       // resolved path (the name glslang reports errors with)
  std::string includer;   // the path of the including file as glslang named it
  std::string requested;  // as written between the quotes or brackets
  bool system = false;    // <x> rather than "x"
};

// Why an #include was refused although the file exists: glslang only says
// it "could not process" it, so the includer keeps the reason.
struct IncludeRefusal {
  std::string header;  // as requested
  DiagId id = DiagId::backend_include_not_found;
  std::string message;
  std::string note;
  // When the reason lies inside the file (a hazard, a macro bomb): the
  // file, its text and the offset there. Otherwise the #include is blamed.
  std::string path;
  std::string text;
  size_t offset = 0;
  // A budget of the whole program (count, bytes): later includes are
  // refused for it too, and only the first is reported.
  bool budget = false;
};

class FileIncluder final : public glslang::TShader::Includer {
 public:
  // `scan_cache` (may be null) shares the scans of included texts with the
  // other includers of the same Backend.
  FileIncluder(const BackendOptions& options, std::string stdlib_dir,
               std::shared_ptr<IncludeScanCache> scan_cache = nullptr);
  ~FileIncluder() override;

  IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override;
  IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override;
  void releaseInclude(IncludeResult* result) override;

  const std::vector<IncludeRecord>& records() const { return records_; }
  // The text of a file this includer returned (nullptr if never returned).
  const std::string* text_of(const std::string& path) const;
  // Why `header` was refused, when the file was found but refused (too
  // deep, a budget exceeded, text glslang cannot take); nullptr otherwise.
  const IncludeRefusal* refusal(const std::string& header) const;
  // The macro-expansion estimate of the program (macro_budget.h): the
  // program's own chunks go in before glslang runs, included files as
  // they are returned.
  MacroBudget& macro_budget() { return macro_budget_; }
  // Global uniforms the program assigns to: their declarations in included
  // files are rewritten (rewrite_assigned_uniforms).
  void set_assigned_uniforms(std::vector<std::string> names) { assigned_uniforms_ = std::move(names); }
  // Texts served instead of these files' contents (calls given casts).
  void set_overrides(std::map<std::string, std::string> texts) { overrides_ = std::move(texts); }
  // Every file returned so far, by path.
  std::map<std::string, std::string> returned_texts() const {
    return std::map<std::string, std::string>(texts_.begin(), texts_.end());
  }
  // Where `#include <x>` looks, in order (for the "not found" note).
  std::vector<std::string> search_dirs(const std::string& includer) const;

 private:
  IncludeResult* found(std::string path, std::string text, const char* header, const char* includer, bool system);
  IncludeResult* refuse(IncludeRefusal refusal);
  // A budget refusal already given, or one `size` more bytes would cause.
  std::optional<IncludeRefusal> over_budget(const char* header, uint64_t size) const;
  std::optional<IncludeRefusal> check_text(const std::string& path, const ScannedText& text, const char* header);
  IncludeResult* search(const std::vector<std::string>& dirs, const char* header, const char* includer, bool system);

  const BackendOptions& options_;
  std::string stdlib_dir_;
  std::shared_ptr<IncludeScanCache> scan_cache_;
  std::vector<IncludeRecord> records_;
  std::vector<IncludeRefusal> refusals_;
  MacroBudget macro_budget_;
  uint64_t include_count_ = 0, include_bytes_ = 0;
  std::vector<std::string> assigned_uniforms_;
  std::map<std::string, std::string> overrides_;
  std::deque<std::pair<std::string, std::string>> texts_;  // path, text; stable addresses
};

// An includer for one compile of `program`, its macro budget fed the
// program's prelude and chunks; nullptr, with a located error, when that
// text would overflow glslang's stack (find_recursion_hazard) or expands
// past the budget (MacroBudget).
std::unique_ptr<FileIncluder> checked_includer(const ir::Program& program, const AssembledSource& source,
                                               const BackendOptions& options, const std::string& stdlib_dir,
                                               Diagnostics& diags,
                                               std::shared_ptr<IncludeScanCache> scan_cache = nullptr);

// Reads a whole file; nullopt when it cannot be read (or is not a regular file).
std::optional<std::string> read_text_file(const std::string& path);

}  // namespace facet::backend
