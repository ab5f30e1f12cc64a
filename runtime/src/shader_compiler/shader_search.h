// Unity's Shader.Find for files: the .shader that declares a shader name.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace facet::runtime {

// The first .shader under `dirs` (each with its subfolders; in order, files
// in path order) whose ShaderLab declares `Shader "name"`. Files that cannot
// be read or parsed are passed over.
std::optional<std::string> find_shader_file(const std::vector<std::string>& dirs, const std::string& name);

}  // namespace facet::runtime
