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

class FileIncluder final : public glslang::TShader::Includer {
 public:
  FileIncluder(const BackendOptions& options, std::string stdlib_dir);
  ~FileIncluder() override;

  IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override;
  IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override;
  void releaseInclude(IncludeResult* result) override;

  const std::vector<IncludeRecord>& records() const { return records_; }
  // The text of a file this includer returned (nullptr if never returned).
  const std::string* text_of(const std::string& path) const;
  // Whether `header` was refused because includes nested too deeply.
  bool too_deep(const std::string& header) const;
  // Whether `header` was refused because its brackets nest too deeply.
  bool too_nested(const std::string& header) const;
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
  IncludeResult* search(const std::vector<std::string>& dirs, const char* header, const char* includer, bool system);

  const BackendOptions& options_;
  std::string stdlib_dir_;
  std::vector<IncludeRecord> records_;
  std::vector<std::string> too_deep_, too_nested_;
  std::vector<std::string> assigned_uniforms_;
  std::map<std::string, std::string> overrides_;
  std::deque<std::pair<std::string, std::string>> texts_;  // path, text; stable addresses
};

// Reads a whole file; nullopt when it cannot be read.
std::optional<std::string> read_text_file(const std::string& path);

}  // namespace facet::backend
