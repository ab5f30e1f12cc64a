#include "backend/includer.h"

#include "backend/hlsl_rewrite.h"
#include "backend/source_assembly.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace facet::backend {
namespace fs = std::filesystem;
namespace {

bool is_real_path(const std::string& name) { return !name.empty() && name.front() != '<'; }

// GLSL includes (Unity's .glslinc) get no HLSL rewrites.
bool is_glsl_file(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  return ext == ".glslinc" || ext == ".glsl";
}

}  // namespace

std::optional<std::string> read_text_file(const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

FileIncluder::FileIncluder(const BackendOptions& options, std::string stdlib_dir)
    : options_(options), stdlib_dir_(std::move(stdlib_dir)) {}

FileIncluder::~FileIncluder() = default;

bool FileIncluder::too_deep(const std::string& header) const {
  return std::find(too_deep_.begin(), too_deep_.end(), header) != too_deep_.end();
}

bool FileIncluder::too_nested(const std::string& header) const {
  return std::find(too_nested_.begin(), too_nested_.end(), header) != too_nested_.end();
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

glslang::TShader::Includer::IncludeResult* FileIncluder::found(std::string path, std::string text, const char* header,
                                                                const char* includer, bool system) {
  records_.push_back({path, includer ? includer : "", header, system});
  if (auto o = overrides_.find(path); o != overrides_.end()) text = o->second;
  if (text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);  // a UTF-8 byte-order mark: glslang rejects it
  if (!is_glsl_file(path)) text = rewrite_assigned_uniforms(rewrite_matrix_swizzles(text), assigned_uniforms_);
  texts_.emplace_back(std::move(path), std::move(text));
  const auto& [p, t] = texts_.back();
  return new IncludeResult(p, t.data(), t.size(), nullptr);
}

glslang::TShader::Includer::IncludeResult* FileIncluder::search(const std::vector<std::string>& dirs,
                                                                 const char* header, const char* includer,
                                                                 bool system) {
  for (const std::string& dir : dirs) {
    fs::path candidate = (dir.empty() ? fs::path(header) : fs::path(dir) / header).lexically_normal();
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
  if (depth > kMaxIncludeDepth) {
    too_deep_.push_back(header);
    return nullptr;
  }
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
  if (depth > kMaxIncludeDepth) {
    too_deep_.push_back(header);
    return nullptr;
  }
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

}  // namespace facet::backend
