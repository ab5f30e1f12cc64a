// How the renderer gets a .shader's passes and variants: through a
// ShaderCompiler, which the runtime itself never implements. Without one
// (RenderOptions::shader_compiler empty) the renderer draws packages only
// (.facetpkg, built offline by facetc) and links no compiler; the
// development layer, facet_shader_compiler (make_shader_compiler below),
// implements it over facet::Compiler, so that a scene may name .shader files
// whose variants are compiled when a draw first needs them.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "facet/compiler.h"  // SelectedPass and the IR (header only: nothing of the compiler is linked)
#include "facet/package.h"
#include "facet/result.h"
#include "facet/source.h"

namespace facet::runtime {

// A .shader as the renderer draws it: its IR, the passes of the SubShader in
// use, its render queue, and the source map its messages point into.
struct ShaderSource {
  SourceMap sources;
  ir::Shader shader;
  std::vector<SelectedPass> passes;
  int queue = 2000;
};

// One pass's one variant, compiled: a package holding just it, and every
// file its compile read.
struct CompiledPassVariant {
  package::Package package;
  std::vector<std::string> files_read;
};

struct ShaderCompiler {
  // Loads a .shader. On failure the compiler's diagnostics are in `diags`,
  // located in `report` (the files they point into are added to it).
  std::function<Result<ShaderSource>(const std::string& path, SourceMap& report, Diagnostics& diags)> load;
  // Compiles one pass of a loaded shader (`pass`: SelectedPass::pass, the
  // pass's index in its SubShader) with exactly these keywords; `sources`
  // gains the files the compile reads, and the diagnostics of a failure
  // point into it.
  std::function<Result<CompiledPassVariant>(const ir::Shader& shader, SourceMap& sources, size_t pass,
                                            const std::vector<std::string>& keywords, Diagnostics& diags)>
      compile;
  // The .shader that declares the shader `name` (`Shader "name"`), searched
  // for in ShaderCompilerOptions::shader_dirs: where the renderer compiles a
  // variant that a package lacks. nullopt when no file declares it.
  std::function<std::optional<std::string>(const std::string& name)> find;
  // Why a SPIR-V module of a package file may not reach the driver, or
  // nullopt: a package's checksum finds damage, not an edit whose checksum
  // was recomputed (its seed is public), and drivers crash on invalid
  // SPIR-V. The development layer runs spirv-val (its first message), on
  // each module the first time a draw needs it; empty (a runtime without
  // the compiler), packages are trusted as any compiled code is.
  std::function<std::optional<std::string>(const std::vector<uint32_t>& module)> spirv_problem;
  // The stdlib's folder (its Shaders/ holds the procedural sky).
  std::string stdlib_dir;
};

struct ShaderCompilerOptions {
  std::string cache_dir;                  // the compiler's cache folder; empty: none
  std::vector<std::string> include_dirs;  // #include search folders (facetc -I)
  // Folders searched, with their subfolders, for the .shader a package was
  // built from, by the shader's name: in order, files in path order, the
  // first that declares the name wins.
  std::vector<std::string> shader_dirs;
};

// The development layer (link facet_shader_compiler): a ShaderCompiler over
// facet::Compiler. Defined there, not in facet_render.
std::shared_ptr<const ShaderCompiler> make_shader_compiler(const ShaderCompilerOptions& options = {});

}  // namespace facet::runtime
