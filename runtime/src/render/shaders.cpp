#include "render/shaders.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

#include "facet/package_file.h"
#include "facet/support/render_queue.h"
#include "facet/support/text.h"

namespace facet::runtime {
namespace {

struct Timer {
  double& total;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  ~Timer() { total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); }
};

bool is_package_path(const std::string& path) { return path.ends_with(".facetpkg"); }

// A package's passes as the renderer's passes: name, tags, render state and
// keyword space as the build saw them, and the stages its variants hold.
void adopt_package(ShaderAsset& asset, package::Package pkg) {
  asset.shader.name = pkg.shader_name;
  asset.shader.properties = pkg.properties;
  asset.queue = 2000;
  for (const ir::Tag& tag : pkg.subshader_tags) {
    if (!iequals(tag.key, "Queue")) continue;
    if (std::optional<int> queue = queue_number(tag.value)) asset.queue = *queue;
  }
  for (size_t p = 0; p < pkg.passes.size(); ++p) {
    const package::PackagePass& built = pkg.passes[p];
    SelectedPass pass{.subshader = 0, .pass = p, .keywords = built.keywords};
    pass.ir.kind = ir::PassKind::normal;
    pass.ir.name = built.name;
    pass.ir.tags = built.tags;
    pass.ir.state = built.state;
    pass.ir.program.emplace();
    std::vector<variants::VariantKey>& keys = asset.available.emplace_back();
    for (const package::PackageVariant& v : built.variants) {
      keys.push_back(v.key);
      for (const package::PackageStage& st : v.stages) pass.ir.program->entry_points[size_t(st.stage)] = "main";
    }
    asset.passes.push_back(std::move(pass));
  }
  asset.package = std::move(pkg);
}

}  // namespace

Result<ShaderAsset*, std::string> ShaderLibrary::load(const std::string& path) {
  if (auto it = shaders_.find(path); it != shaders_.end()) return it->second.get();
  Timer timer{seconds_};
  auto asset = std::make_unique<ShaderAsset>();
  asset->path = path;
  asset->files_read.insert(path);
  Diagnostics diags;
  if (is_package_path(path)) {
    Result<package::Package> pkg = read_package_file(path, diags);
    if (!pkg) return unexpected(render_text(diags, asset->sources));
    adopt_package(*asset, std::move(*pkg));
    ShaderAsset* raw = asset.get();
    shaders_[path] = std::move(asset);
    return raw;
  }
  if (!compiler_ || !compiler_->load || !compiler_->compile) {
    return unexpected(fmt::format("{}: a .shader needs the development layer (facet_shader_compiler) to compile its "
                                  "variants; this renderer draws packages only: build it with `facetc {} -o NAME.facetpkg` "
                                  "and name the package in the scene",
                                  path, path));
  }
  Result<ShaderSource, std::string> source = compiler_->load(path);
  if (!source) return unexpected(source.error());
  asset->sources = std::move(source->sources);
  asset->shader = std::move(source->shader);
  asset->passes = std::move(source->passes);
  asset->queue = source->queue;
  ShaderAsset* raw = asset.get();
  shaders_[path] = std::move(asset);
  return raw;
}

std::vector<std::string> ShaderLibrary::files_read() const {
  std::set<std::string> all;
  for (const auto& [path, asset] : shaders_) all.insert(asset->files_read.begin(), asset->files_read.end());
  return {all.begin(), all.end()};
}

Result<LoadedVariant*, std::string> ShaderLibrary::variant(const Context& context, ShaderAsset& asset, size_t pass,
                                                             const variants::VariantKey& key, bool* compiled) {
  auto id = std::make_pair(pass, key);
  if (auto it = asset.variants.find(id); it != asset.variants.end()) {
    *compiled = false;
    return it->second.get();
  }
  Timer timer{seconds_};
  if (asset.package) return packaged_variant(context, asset, pass, key, compiled);
  const size_t selected_pass = asset.passes[pass].pass;
  Result<CompiledPassVariant, std::string> out = compiler_->compile(
      asset.shader, asset.sources, selected_pass, variants::all_keywords(asset.passes[pass].keywords, key));
  if (!out) return unexpected(out.error());
  asset.files_read.insert(out->files_read.begin(), out->files_read.end());
  auto variant = std::make_unique<LoadedVariant>();
  variant->package = std::move(out->package);
  if (variant->package.passes.size() != 1 || variant->package.passes[0].variants.size() != 1) {
    return unexpected(fmt::format("{}: compiling pass {} gave no single variant", asset.path, selected_pass));
  }
  const package::PackageVariant& v = variant->package.passes[0].variants[0];
  variant->keywords = v.keywords;
  Result<std::unique_ptr<GpuProgram>, std::string> program = create_program(context, variant->package, v);
  if (!program) return unexpected(fmt::format("{}: pass {}: {}", asset.path, selected_pass, program.error()));
  variant->program = std::move(*program);
  LoadedVariant* raw = variant.get();
  asset.variants[id] = std::move(variant);
  *compiled = true;
  return raw;
}

Result<LoadedVariant*, std::string> ShaderLibrary::packaged_variant(const Context& context, ShaderAsset& asset,
                                                                     size_t pass, const variants::VariantKey& key,
                                                                     bool* compiled) {
  const std::vector<package::PackageVariant>& built = asset.package->passes[pass].variants;
  auto found = std::find_if(built.begin(), built.end(), [&](const package::PackageVariant& v) { return v.key == key; });
  if (found == built.end()) {
    return unexpected(fmt::format("{}: pass {}: the package has no variant {{{}}}", asset.path, pass,
                                  fmt::join(variants::all_keywords(asset.passes[pass].keywords, key), " ")));
  }
  auto variant = std::make_unique<LoadedVariant>();
  variant->keywords = found->keywords;
  Result<std::unique_ptr<GpuProgram>, std::string> program = create_program(context, *asset.package, *found);
  if (!program) return unexpected(fmt::format("{}: pass {}: {}", asset.path, pass, program.error()));
  variant->program = std::move(*program);
  LoadedVariant* raw = variant.get();
  asset.variants[{pass, key}] = std::move(variant);
  *compiled = false;  // it was built offline
  return raw;
}

}  // namespace facet::runtime
