#include "includer.h"

#include "hlsl_rewrite.h"
#include "source_assembly.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace facet::backend {
namespace fs = std::filesystem;
namespace {

bool is_real_path(const std::string& name) { return !name.empty() && name.front() != '<'; }

// GLSL includes (Unity's .glslinc) get no HLSL rewrites.
bool is_glsl_file(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  return ext == ".glslinc" || ext == ".glsl";
}

IncludeRefusal too_deep(const char* header) {
  return IncludeRefusal{.header = header,
                        .message = fmt::format("#include nested more than {} deep", kMaxIncludeDepth),
                        .note = fmt::format("does '{}' include itself without an include guard?", header)};
}

// The program's chunks, in the order glslang sees them.
std::vector<const ir::SourceChunk*> chunks_of(const ir::Program& program) {
  std::vector<const ir::SourceChunk*> chunks;
  for (const ir::SourceChunk& chunk : program.includes) chunks.push_back(&chunk);
  chunks.push_back(&program.body);
  return chunks;
}

SourceSpan span_at(const ir::SourceChunk& chunk, size_t offset) {
  SourceSpan span = chunk.span;
  if (span.has_location()) span = {span.file, span.begin + uint32_t(offset), span.begin + uint32_t(offset) + 1};
  return span;
}

// Refuses chunks that nest deeper than glslang can parse safely
// (find_recursion_hazard), and feeds the macro budget the prelude and the
// chunks; false, with a located error, when either refuses.
bool check_program_text(const ir::Program& program, const AssembledSource& source, MacroBudget& budget,
                        Diagnostics& diags) {
  for (const ir::SourceChunk* chunk : chunks_of(program)) {
    if (auto hazard = find_recursion_hazard(chunk->text)) {
      diags.add(DiagId::backend_nesting_too_deep, span_at(*chunk, hazard->offset), hazard->message);
      return false;
    }
  }
  if (auto excess = budget.add_text(source.prelude)) {
    diags.add(DiagId::backend_input_limit, SourceSpan{}, excess->message);
    return false;
  }
  for (const ir::SourceChunk* chunk : chunks_of(program)) {
    if (auto excess = budget.add_text(chunk->text)) {
      diags.add(DiagId::backend_input_limit, span_at(*chunk, excess->offset), excess->message);
      return false;
    }
  }
  return true;
}

}  // namespace

std::optional<std::string> read_text_file(const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  // Read in one piece (the file may grow or shrink meanwhile: what was read counts).
  std::string text;
  in.seekg(0, std::ios::end);
  std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  if (size > 0) {
    text.resize(size_t(size));
    in.read(text.data(), size);
    text.resize(size_t(in.gcount()));
  }
  if (in.bad()) return std::nullopt;
  return text;
}

FileIncluder::FileIncluder(const BackendOptions& options, std::string stdlib_dir,
                           std::shared_ptr<IncludeScanCache> scan_cache)
    : options_(options),
      stdlib_dir_(std::move(stdlib_dir)),
      scan_cache_(std::move(scan_cache)),
      macro_budget_(options.limits.max_preprocessed_bytes) {}

FileIncluder::~FileIncluder() = default;

const IncludeRefusal* FileIncluder::refusal(const std::string& header) const {
  for (const IncludeRefusal& r : refusals_) {
    if (r.header == header) return &r;
  }
  return nullptr;
}

const std::string* FileIncluder::text_of(const std::string& path) const {
  for (const auto& [p, text] : texts_) {
    if (p == path) return &text;
  }
  return nullptr;
}

std::vector<std::string> FileIncluder::search_dirs(const std::string& includer) const {
  std::vector<std::string> dirs;
  if (!options_.resolver && is_real_path(includer)) dirs.push_back(fs::path(includer).parent_path().string());
  if (!options_.resolver) dirs.insert(dirs.end(), options_.include_dirs.begin(), options_.include_dirs.end());
  if (!stdlib_dir_.empty()) dirs.push_back(stdlib_dir_);
  return dirs;
}

glslang::TShader::Includer::IncludeResult* FileIncluder::refuse(IncludeRefusal refusal) {
  refusals_.push_back(std::move(refusal));
  return nullptr;
}

std::optional<IncludeRefusal> FileIncluder::over_budget(const char* header, uint64_t size) const {
  for (const IncludeRefusal& r : refusals_) {
    if (r.budget) return IncludeRefusal{.header = header, .message = r.message, .budget = true};
  }
  const InputLimits& limits = options_.limits;
  if (size > kMaxIncludeFileBytes) {
    return IncludeRefusal{.header = header,
                          .message = fmt::format("'{}' is larger than {} MiB ({} bytes)", header,
                                                 kMaxIncludeFileBytes >> 20, size)};
  }
  if (limits.max_includes != 0 && include_count_ + 1 > limits.max_includes) {
    return IncludeRefusal{.header = header,
                          .message = fmt::format("more than {} #includes in one program (--max-includes)",
                                                 limits.max_includes),
                          .note = "does a file include others more than once without an include guard?",
                          .budget = true};
  }
  if (limits.max_include_bytes != 0 && include_bytes_ + size > limits.max_include_bytes) {
    return IncludeRefusal{.header = header,
                          .message = fmt::format("the program's included files exceed {} bytes together "
                                                 "(--max-include-bytes)",
                                                 limits.max_include_bytes),
                          .note = "does a file include others more than once without an include guard?",
                          .budget = true};
  }
  return std::nullopt;
}

// Text glslang must not see: what would overflow its stack, or expand
// past the program's budget.
std::optional<IncludeRefusal> FileIncluder::check_text(const std::string& path, const ScannedText& scanned,
                                                       const char* header) {
  if (const std::optional<RecursionHazard>& hazard = scanned.hazard) {
    return IncludeRefusal{.header = header, .id = DiagId::backend_nesting_too_deep, .message = hazard->message,
                          .path = path, .text = scanned.text, .offset = hazard->offset};
  }
  if (auto excess = macro_budget_.add_lines(scanned.lines)) {
    return IncludeRefusal{.header = header, .id = DiagId::backend_input_limit, .message = excess->message,
                          .path = path, .text = scanned.text, .offset = excess->offset, .budget = true};
  }
  return std::nullopt;
}

glslang::TShader::Includer::IncludeResult* FileIncluder::found(std::string path, std::string text, const char* header,
                                                                const char* includer, bool system) {
  if (auto refusal = over_budget(header, text.size())) return refuse(std::move(*refusal));
  ++include_count_;
  include_bytes_ += text.size();
  if (auto o = overrides_.find(path); o != overrides_.end()) text = o->second;
  while (text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);  // UTF-8 byte-order marks: glslang rejects them
  std::shared_ptr<const ScannedText> scanned = scan_cache_ ? scan_cache_->scan(std::move(text)) : scan_text(std::move(text));
  if (auto refusal = check_text(path, *scanned, header)) return refuse(std::move(*refusal));
  records_.push_back({path, includer ? includer : "", header, system});
  text = is_glsl_file(path) ? scanned->text
                            : rewrite_assigned_uniforms(rewrite_matrix_swizzles(scanned->text), assigned_uniforms_);
  texts_.emplace_back(std::move(path), std::move(text));
  const auto& [p, t] = texts_.back();
  return new IncludeResult(p, t.data(), t.size(), nullptr);
}

glslang::TShader::Includer::IncludeResult* FileIncluder::search(const std::vector<std::string>& dirs,
                                                                 const char* header, const char* includer,
                                                                 bool system) {
  // "..\CGIncludes\Core.cginc": shaders written on Windows separate with
  // backslashes, which Unity accepts everywhere.
  std::string name = header;
  std::replace(name.begin(), name.end(), '\\', '/');
  for (const std::string& dir : dirs) {
    fs::path candidate = (dir.empty() ? fs::path(name) : fs::path(dir) / name).lexically_normal();
    std::error_code size_error;
    if (!fs::is_regular_file(candidate, size_error)) continue;
    // Too large: refused by its size, unread.
    if (uint64_t size = fs::file_size(candidate, size_error); !size_error && size > kMaxIncludeFileBytes) {
      if (auto refusal = over_budget(header, size)) return refuse(std::move(*refusal));
    }
    if (auto text = read_text_file(candidate.string())) {
      std::error_code ec;
      fs::path absolute = fs::absolute(candidate, ec);
      return found(ec ? candidate.string() : absolute.lexically_normal().string(), std::move(*text), header,
                   includer, system);
    }
  }
  return nullptr;
}

glslang::TShader::Includer::IncludeResult* FileIncluder::includeLocal(const char* header, const char* includer,
                                                                       size_t depth) {
  if (depth > kMaxIncludeDepth) return refuse(too_deep(header));
  std::string from = includer ? includer : "";
  if (options_.resolver) {
    if (auto file = options_.resolver(header, from)) return found(file->path, file->text, header, includer, false);
    return nullptr;
  }
  if (!is_real_path(from)) return nullptr;
  return search({fs::path(from).parent_path().string()}, header, includer, false);
}

glslang::TShader::Includer::IncludeResult* FileIncluder::includeSystem(const char* header, const char* includer,
                                                                        size_t depth) {
  if (depth > kMaxIncludeDepth) return refuse(too_deep(header));
  std::vector<std::string> dirs;
  if (options_.resolver) {
    if (auto file = options_.resolver(header, includer ? includer : "")) {
      return found(file->path, file->text, header, includer, true);
    }
  } else {
    dirs = options_.include_dirs;
  }
  if (!stdlib_dir_.empty()) dirs.push_back(stdlib_dir_);
  return search(dirs, header, includer, true);
}

void FileIncluder::releaseInclude(IncludeResult* result) { delete result; }

// An includer whose macro budget has read the program's own text; nullptr,
// with a located error, when that text is refused (check_program_text).
std::unique_ptr<FileIncluder> checked_includer(const ir::Program& program, const AssembledSource& source,
                                               const BackendOptions& options, const std::string& stdlib_dir,
                                               Diagnostics& diags, std::shared_ptr<IncludeScanCache> scan_cache) {
  auto includer = std::make_unique<FileIncluder>(options, stdlib_dir, std::move(scan_cache));
  if (!check_program_text(program, source, includer->macro_budget(), diags)) return nullptr;
  return includer;
}


}  // namespace facet::backend
