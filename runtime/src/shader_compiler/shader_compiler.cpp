// The development layer: .shader files loaded and their variants compiled
// through facet::Compiler, one pass and one variant per compile.
#include <string>
#include <utility>

#include <fmt/format.h>

#include "facet/backend.h"
#include "facet/compiler.h"
#include "facet/runtime/shader_compiler.h"
#include "facet/shader_search.h"

namespace facet::runtime {
namespace {

// spirv-val's first message about `module`, or nullopt when it is valid.
std::optional<std::string> spirv_problem(const std::vector<uint32_t>& module) {
  Diagnostics found;
  if (backend::validate(module, backend::TargetEnv::vulkan1_2, found)) return std::nullopt;
  return found.all().empty() ? std::string("spirv-val refused it") : found.all()[0].message;
}

}  // namespace

std::shared_ptr<const ShaderCompiler> make_shader_compiler(const ShaderCompilerOptions& options) {
  auto compiler = std::make_shared<const Compiler>();
  auto out = std::make_shared<ShaderCompiler>();
  out->stdlib_dir = default_stdlib_dir();
  out->load = [compiler, options](const std::string& path, SourceMap& report,
                                  Diagnostics& diags) -> Result<ShaderSource> {
    ShaderSource source;
    Diagnostics found;
    auto failed = [&] {
      diags.append(rebase_diagnostics(found, source.sources, report));
      return failure();
    };
    CompileOptions load_options;
    load_options.backend.include_dirs = options.include_dirs;
    Result<ir::Shader> shader = compiler->load(path, source.sources, found, load_options);
    if (!shader) return failed();
    source.shader = std::move(*shader);
    Result<std::vector<SelectedPass>> passes = compiler->select_passes(source.shader, {}, found);
    if (!passes) return failed();
    source.passes = std::move(*passes);
    if (!source.passes.empty()) source.queue = source.shader.subshaders[source.passes[0].subshader].queue;
    return source;
  };
  out->compile = [compiler, options](const ir::Shader& shader, SourceMap& sources, size_t pass,
                                     const std::vector<std::string>& keywords,
                                     Diagnostics& diags) -> Result<CompiledPassVariant> {
    CompileOptions compile_options;
    compile_options.passes = {std::to_string(pass)};
    compile_options.keywords = keywords;
    compile_options.cache_dir = options.cache_dir;
    compile_options.backend.include_dirs = options.include_dirs;
    Result<CompiledShader> compiled = compiler->compile(shader, compile_options, sources, diags);
    if (!compiled) return failure();
    // A compile validates its own modules; one from a cache entry may have
    // been edited there.
    for (size_t i = 0; !options.cache_dir.empty() && i < compiled->package.spirv_blobs.size(); ++i) {
      if (std::optional<std::string> why = spirv_problem(compiled->package.spirv_blobs[i])) {
        diags.add(DiagId::shader_unavailable, SourceSpan{},
                  fmt::format("{}: SPIR-V module {} from the compile cache '{}' is not valid SPIR-V, so it is not "
                              "given to the driver ({})",
                              sources.path(shader.file), i, options.cache_dir, *why));
        return failure();
      }
    }
    return CompiledPassVariant{std::move(compiled->package),
                               {compiled->dependencies.begin(), compiled->dependencies.end()}};
  };
  out->spirv_problem = spirv_problem;
  if (!options.shader_dirs.empty()) {
    std::vector<ShaderDir> dirs;
    for (const std::string& dir : options.shader_dirs) dirs.push_back({dir, true});
    out->find = [dirs = std::move(dirs)](const std::string& name) { return find_shader_file(dirs, name); };
  }
  return out;
}

}  // namespace facet::runtime
