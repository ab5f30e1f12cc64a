#include "render/shaders.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

#include "facet/package_file.h"
#include "render/built_in_shaders.h"
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
    SelectedPass pass{.subshader = 0, .pass = built.source_index, .keywords = built.keywords};
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

Result<ShaderAsset*, Diagnostics> ShaderLibrary::load(const std::string& path) {
  used_.insert(path);
  if (auto it = shaders_.find(path); it != shaders_.end()) return it->second.get();
  Timer timer{seconds_};
  auto asset = std::make_unique<ShaderAsset>();
  asset->path = path;
  ++loads_;
  note_read(*asset, path);
  Diagnostics diags;
  if (is_package_path(path)) {
    Result<package::Package> pkg = read_package_file(path, diags);
    if (!pkg) return unexpected(rebase_diagnostics(diags, asset->sources, report_));
    adopt_package(*asset, std::move(*pkg));
    asset->from_file = true;
    ShaderAsset* raw = asset.get();
    shaders_[path] = std::move(asset);
    return raw;
  }
  if (!compiler_ || !compiler_->load || !compiler_->compile) {
    return unexpected(render_error(
        fmt::format("{}: a .shader needs the development layer (facet_shader_compiler) to compile its variants; this "
                    "renderer draws packages only: build it with `facetc {} -o NAME.facetpkg` and name the package in "
                    "the scene",
                    path, path),
        DiagId::shader_unavailable));
  }
  Result<ShaderSource> source = compiler_->load(path, report_, diags);
  if (!source) return unexpected(diags);
  asset->sources = std::move(source->sources);
  asset->shader = std::move(source->shader);
  asset->passes = std::move(source->passes);
  asset->queue = source->queue;
  ShaderAsset* raw = asset.get();
  shaders_[path] = std::move(asset);
  return raw;
}

Result<ShaderAsset*, Diagnostics> ShaderLibrary::load_built_in(const std::string& file) {
  if (compiler_ && compiler_->load && !compiler_->stdlib_dir.empty()) return load(compiler_->stdlib_dir + "/Shaders/" + file);
  const std::string key = "<built-in>/" + file;
  used_.insert(key);
  if (auto it = shaders_.find(key); it != shaders_.end()) return it->second.get();
  std::span<const uint8_t> bytes = built_in_package(file);
  if (bytes.empty()) {
    return unexpected(render_error(fmt::format("{} is not one of the renderer's built-in shaders", file),
                                   DiagId::shader_unavailable));
  }
  Timer timer{seconds_};
  auto asset = std::make_unique<ShaderAsset>();
  asset->path = key;
  Diagnostics diags;
  Result<package::Package> pkg = package::read_package(bytes, diags);
  if (!pkg) {
    return unexpected(render_error_in(key + ": the built-in package does not read", DiagId::shader_unavailable,
                                      rebase_diagnostics(diags, asset->sources, report_)));
  }
  ++loads_;
  adopt_package(*asset, std::move(*pkg));
  ShaderAsset* raw = asset.get();
  shaders_[key] = std::move(asset);
  return raw;
}

FileStamp stamp_of(const std::string& path) {
  std::error_code ec;
  FileStamp stamp;
  stamp.time = std::filesystem::last_write_time(path, ec);
  if (ec) return {};
  stamp.size = std::filesystem::file_size(path, ec);
  if (ec) return {};
  stamp.exists = true;
  return stamp;
}

void ShaderLibrary::note_read(ShaderAsset& asset, const std::string& path) {
  if (asset.files_read.insert(path).second) asset.stamps[path] = stamp_of(path);
}

size_t ShaderLibrary::forget_changed() {
  size_t forgotten = 0;
  for (auto it = shaders_.begin(); it != shaders_.end();) {
    const std::map<std::string, FileStamp>& stamps = it->second->stamps;
    bool changed = std::any_of(stamps.begin(), stamps.end(),
                               [](const auto& file) { return stamp_of(file.first) != file.second; });
    if (changed) {
      it = shaders_.erase(it);
      ++forgotten;
    } else {
      ++it;
    }
  }
  forgotten_total_ += forgotten;
  return forgotten;
}

std::shared_ptr<ShaderStore> make_shader_store() { return std::make_shared<ShaderStore>(); }

std::vector<std::string> ShaderLibrary::files_read() const {
  std::set<std::string> all;
  for (const auto& [path, asset] : shaders_) {
    if (used_.count(path)) all.insert(asset->files_read.begin(), asset->files_read.end());
  }
  return {all.begin(), all.end()};
}

Result<LoadedVariant*, Diagnostics> ShaderLibrary::variant(const Context& context, ShaderAsset& asset, size_t pass,
                                                           const variants::VariantKey& key, bool* compiled) {
  auto id = std::make_pair(pass, key);
  *compiled = false;
  if (auto it = asset.variants.find(id); it != asset.variants.end()) return it->second.get();
  Timer timer{seconds_};
  Result<std::unique_ptr<LoadedVariant>, Diagnostics> variant =
      asset.package ? packaged_variant(context, asset, pass, key, compiled)
                    : compiled_variant(context, asset, asset.shader, asset.sources, asset.passes[pass].pass,
                                       variants::all_keywords(asset.passes[pass].keywords, key), compiled);
  if (!variant) return unexpected(variant.error());
  LoadedVariant* raw = variant->get();
  asset.variants[id] = std::move(*variant);
  return raw;
}

Result<std::unique_ptr<LoadedVariant>, Diagnostics> ShaderLibrary::compiled_variant(
    const Context& context, ShaderAsset& asset, const ir::Shader& shader, SourceMap& sources, size_t selected_pass,
    const std::vector<std::string>& keywords, bool* compiled) {
  if (!compiler_ || !compiler_->compile) {
    return unexpected(render_error(fmt::format("{}: pass {}: compiling a variant needs the development layer "
                                               "(RenderOptions::shader_compiler), which this render was not given",
                                               asset.path, selected_pass),
                                   DiagId::shader_unavailable));
  }
  Diagnostics diags;
  Result<CompiledPassVariant> out = compiler_->compile(shader, sources, selected_pass, keywords, diags);
  if (!out) return unexpected(rebase_diagnostics(diags, sources, report_));
  for (const std::string& file : out->files_read) note_read(asset, file);
  auto variant = std::make_unique<LoadedVariant>();
  variant->package = std::move(out->package);
  if (variant->package.passes.size() != 1 || variant->package.passes[0].variants.size() != 1) {
    return unexpected(
        render_error(fmt::format("{}: compiling pass {} gave no single variant", asset.path, selected_pass),
                     DiagId::shader_unavailable));
  }
  const package::PackageVariant& v = variant->package.passes[0].variants[0];
  variant->keywords = v.keywords;
  Result<std::unique_ptr<GpuProgram>, std::string> program = create_program(context, variant->package, v);
  if (!program) {
    return unexpected(render_error(fmt::format("{}: pass {}: {}", asset.path, selected_pass, program.error()),
                                   DiagId::vulkan_failed));
  }
  variant->program = std::move(*program);
  *compiled = true;
  return variant;
}

Result<void, Diagnostics> ShaderLibrary::check_modules(ShaderAsset& asset, const package::PackageVariant& variant) {
  if (!asset.from_file || !compiler_ || !compiler_->spirv_problem) return {};
  for (const package::PackageStage& stage : variant.stages) {
    if (asset.valid_modules.count(stage.blob)) continue;
    if (std::optional<std::string> why = compiler_->spirv_problem(asset.package->spirv_blobs.at(stage.blob))) {
      return unexpected(render_error(fmt::format("{}: SPIR-V module {} is not valid SPIR-V, so it is not given to "
                                                 "the driver ({})",
                                                 asset.path, stage.blob, *why),
                                     DiagId::shader_unavailable));
    }
    asset.valid_modules.insert(stage.blob);
  }
  return {};
}

Result<std::unique_ptr<LoadedVariant>, Diagnostics> ShaderLibrary::packaged_variant(const Context& context,
                                                                                    ShaderAsset& asset, size_t pass,
                                                                                    const variants::VariantKey& key,
                                                                                    bool* compiled) {
  const std::vector<package::PackageVariant>& built = asset.package->passes[pass].variants;
  auto found = std::find_if(built.begin(), built.end(), [&](const package::PackageVariant& v) { return v.key == key; });
  if (found == built.end()) return on_demand_variant(context, asset, pass, key, compiled);
  if (Result<void, Diagnostics> checked = check_modules(asset, *found); !checked) return unexpected(checked.error());
  auto variant = std::make_unique<LoadedVariant>();
  variant->keywords = found->keywords;
  Result<std::unique_ptr<GpuProgram>, std::string> program = create_program(context, *asset.package, *found);
  if (!program) {
    return unexpected(
        render_error(fmt::format("{}: pass {}: {}", asset.path, pass, program.error()), DiagId::vulkan_failed));
  }
  variant->program = std::move(*program);
  return variant;  // built offline: *compiled stays false
}

const std::string* ShaderLibrary::on_demand_source(ShaderAsset& asset, std::string& why) {
  why.clear();
  if (!asset.package || strict_variants_ || !compiler_ || !compiler_->find || !compiler_->load || !compiler_->compile) {
    return nullptr;
  }
  // A failed search is tried again by the next render (the file may be
  // saved or fixed by then); a found file is kept until it changes.
  if (!asset.origin && asset.origin_searched_render != renders_) {
    asset.origin_searched_render = renders_;
    Timer timer{seconds_};
    std::optional<std::string> path = compiler_->find(asset.shader.name);
    if (!path) {
      asset.origin_missing = fmt::format("no .shader in the shader folders declares '{}'", asset.shader.name);
    } else {
      Diagnostics diags;
      Result<ShaderSource> source = compiler_->load(*path, report_, diags);
      if (!source) {
        asset.origin_missing = fmt::format("{} declares '{}' but does not load:\n{}", *path, asset.shader.name,
                                           render_text(diags, report_));
      } else {
        note_read(asset, *path);
        asset.origin = ShaderAsset::Origin{*path, std::move(*source)};
      }
    }
  }
  if (!asset.origin) {
    why = asset.origin_missing;
    return nullptr;
  }
  return &asset.origin->path;
}

Result<std::unique_ptr<LoadedVariant>, Diagnostics> ShaderLibrary::on_demand_variant(const Context& context,
                                                                                     ShaderAsset& asset, size_t pass,
                                                                                     const variants::VariantKey& key,
                                                                                     bool* compiled) {
  const package::PackagePass& built = asset.package->passes[pass];
  std::vector<std::string> keywords = variants::all_keywords(built.keywords, key);
  if (!asset.origin) {
    return unexpected(render_error(
        fmt::format("{}: pass {}: the package has no variant {{{}}}", asset.path, pass, fmt::join(keywords, " ")),
        DiagId::variant_missing));
  }
  // The package's pass in the .shader: of the passes with its name and
  // LightMode (several unnamed passes are common), the one at the same rank.
  ShaderSource& source = asset.origin->source;
  std::string light_mode = asset.passes[pass].ir.tag("LightMode");
  auto same = [&](const ir::Pass& p) { return iequals(p.name, built.name) && iequals(p.tag("LightMode"), light_mode); };
  size_t rank = size_t(std::count_if(asset.passes.begin(), asset.passes.begin() + std::ptrdiff_t(pass),
                                     [&](const SelectedPass& p) { return same(p.ir); }));
  auto from = source.passes.begin();
  for (size_t seen = 0; from != source.passes.end(); ++from) {
    if (same(from->ir) && seen++ == rank) break;
  }
  if (from == source.passes.end()) {
    return unexpected(render_error(fmt::format("{}: pass {}: {} has no pass named '{}' with LightMode '{}': it is not "
                                               "the shader the package was built from",
                                               asset.path, pass, asset.origin->path, built.name, light_mode),
                                   DiagId::shader_unavailable));
  }
  Result<std::unique_ptr<LoadedVariant>, Diagnostics> variant =
      compiled_variant(context, asset, source.shader, source.sources, from->pass, keywords, compiled);
  if (!variant) return unexpected(variant.error());
  std::vector<std::string> got = (*variant)->keywords, asked = keywords;
  std::sort(got.begin(), got.end());
  std::sort(asked.begin(), asked.end());
  if (got != asked) {
    return unexpected(
        render_error(fmt::format("{}: pass {}: {} compiles {{{}}} for the keywords {{{}}}: it is not "
                                 "the shader the package was built from",
                                 asset.path, pass, asset.origin->path, fmt::join(got, " "), fmt::join(asked, " ")),
                     DiagId::shader_unavailable));
  }
  return variant;
}

}  // namespace facet::runtime
