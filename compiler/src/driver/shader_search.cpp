#include "facet/shader_search.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "facet/compiler.h"  // kMaxShaderBytes: a larger file is not a candidate
#include "facet/shaderlab.h"
#include "facet/support/read_file.h"

namespace facet {
namespace {

namespace fs = std::filesystem;

bool is_shader_file(const fs::directory_entry& entry) {
  std::error_code ec;  // a dangling link is passed over; the walk goes on
  return entry.path().extension() == ".shader" && entry.is_regular_file(ec);
}

std::vector<std::string> shader_files_in(const ShaderDir& dir) {
  std::vector<std::string> files;
  std::error_code ec;
  if (dir.recursive) {
    fs::recursive_directory_iterator it(dir.path, fs::directory_options::skip_permission_denied, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
      if (is_shader_file(*it)) files.push_back(it->path().string());
    }
  } else {
    fs::directory_iterator it(dir.path, fs::directory_options::skip_permission_denied, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
      if (is_shader_file(*it)) files.push_back(it->path().string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::optional<std::string> declared_name(const std::string& path) {
  Diagnostics diags;
  Result<std::string> text = read_file(path, kMaxShaderBytes, diags);
  if (!text) return std::nullopt;
  SourceMap sources;
  FileId file = sources.add_file(path, std::move(*text));
  Result<shaderlab::ast::Shader> shader = shaderlab::parse(file, sources, {}, diags);
  if (!shader) return std::nullopt;
  return shader->name;
}

}  // namespace

ShaderIndex index_shaders(const std::vector<ShaderDir>& dirs) {
  ShaderIndex index;
  for (const ShaderDir& dir : dirs) {
    for (const std::string& file : shader_files_in(dir)) {
      if (auto name = declared_name(file)) index.emplace(std::move(*name), file);
    }
  }
  return index;
}

std::optional<std::string> find_shader(const ShaderIndex& index, const std::string& name) {
  for (const std::string& candidate : {name, "Legacy Shaders/" + name}) {
    if (auto it = index.find(candidate); it != index.end()) return it->second;
  }
  return std::nullopt;
}

std::optional<std::string> find_shader_file(const std::vector<ShaderDir>& dirs, const std::string& name) {
  return find_shader(index_shaders(dirs), name);
}

}  // namespace facet
