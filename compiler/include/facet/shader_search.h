// Unity's Shader.Find for files: which .shader file declares a shader name.
// The compiler uses it for UsePass and Fallback (docs/language.md), the
// runtime for scenes that name a shader instead of a file.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace facet {

// A folder searched for .shader files, with or without its subfolders.
struct ShaderDir {
  std::string path;
  bool recursive = true;
};

// Shader name -> the first file declaring it: the folders in order, each
// one's files in path order. A file that cannot be read (not a regular file,
// over kMaxShaderBytes) or does not parse is passed over.
using ShaderIndex = std::map<std::string, std::string>;
ShaderIndex index_shaders(const std::vector<ShaderDir>& dirs);

// The file declaring `name`, or, as Unity still finds its built-in shaders
// by their names before 5.0 ("Diffuse", "Transparent/VertexLit"), the one
// declaring "Legacy Shaders/" + name.
std::optional<std::string> find_shader(const ShaderIndex& index, const std::string& name);

// index_shaders then find_shader, for a single lookup.
std::optional<std::string> find_shader_file(const std::vector<ShaderDir>& dirs, const std::string& name);

}  // namespace facet
