#include "shader_search.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "facet/compiler.h"  // kMaxShaderBytes: a larger file is not a candidate
#include "facet/shaderlab.h"
#include "facet/support/read_file.h"

namespace facet::runtime {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> shader_files_under(const std::string& dir) {
  std::vector<std::string> files;
  std::error_code ec;
  fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end;
  for (; !ec && it != end; it.increment(ec)) {
    std::error_code file_error;  // a dangling link is passed over; the walk goes on
    if (it->path().extension() == ".shader" && it->is_regular_file(file_error)) files.push_back(it->path().string());
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

std::optional<std::string> find_shader_file(const std::vector<std::string>& dirs, const std::string& name) {
  for (const std::string& dir : dirs) {
    for (const std::string& file : shader_files_under(dir)) {
      if (declared_name(file) == name) return file;
    }
  }
  return std::nullopt;
}

}  // namespace facet::runtime
