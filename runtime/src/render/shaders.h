// Shaders a scene uses, loaded once each, and their variants compiled on
// first use: one pass and one variant per compile, so a frame costs exactly
// the (pass, variant) pairs its draws need.
#pragma once

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "facet/runtime/shader_compiler.h"
#include "render/failure.h"
#include "render/program.h"

namespace facet::runtime {

// A variant of one pass as the renderer holds it: the one-variant package it
// was compiled into (empty for a variant of a loaded .facetpkg) and its
// program on the GPU.
struct LoadedVariant {
  package::Package package;
  std::unique_ptr<GpuProgram> program;
  std::vector<std::string> keywords;
};

// What tells a file's change on disk: its modification time and size
// (exists false when it could not be read).
struct FileStamp {
  bool exists = false;
  std::filesystem::file_time_type time{};
  uintmax_t size = 0;
  bool operator==(const FileStamp&) const = default;
};
FileStamp stamp_of(const std::string& path);

struct ShaderAsset {
  std::string path;
  SourceMap sources;
  ir::Shader shader;
  std::vector<SelectedPass> passes;  // of the SubShader in use
  int queue = 2000;                  // the SubShader's render queue (sema resolves its Queue tag)
  std::map<std::pair<size_t, variants::VariantKey>, std::unique_ptr<LoadedVariant>> variants;
  std::set<std::string> files_read;  // the .shader and every file its compiled variants included
  // Each file of files_read as it was when read: a change means a reload.
  std::map<std::string, FileStamp> stamps;
  // Loaded from a .facetpkg: its passes' variants are all there is (nothing
  // is compiled), and `available` lists each pass's variant keys for the
  // selection rule.
  std::optional<package::Package> package;
  std::vector<std::vector<variants::VariantKey>> available;
  // Read from a .facetpkg file (not built in): its modules are checked
  // (ShaderCompiler::spirv_problem) as draws first need them.
  bool from_file = false;
  std::set<uint32_t> valid_modules;  // blob indices checked
  // A package's .shader, found by the shader's name through the development
  // layer on the first draw the package has no exact variant for: the
  // variants it lacks are compiled from it.
  struct Origin {
    std::string path;
    ShaderSource source;
  };
  std::optional<Origin> origin;
  uint64_t origin_searched_render = UINT64_MAX;  // ShaderLibrary's render number of the last search
  std::string origin_missing;                    // why there is no origin, after a search
};

class ShaderLibrary {
 public:
  // `compiler` empty: packages only.
  explicit ShaderLibrary(std::shared_ptr<const ShaderCompiler> compiler) : compiler_(std::move(compiler)) {}

  // A .facetpkg built by facetc, or a .shader through the ShaderCompiler.
  // Errors are the compiler's or the package reader's diagnostics, located
  // in report_sources().
  Result<ShaderAsset*, Diagnostics> load(const std::string& path);
  // The stdlib's Shaders/<file>, which the renderer draws by itself: its
  // .shader through the development layer (an edited stdlib shows), else the
  // package built into facet_render (built_in_shaders.h).
  Result<ShaderAsset*, Diagnostics> load_built_in(const std::string& file);
  // The variant of pass `pass` (an index into asset.passes) with this key,
  // compiled and on the GPU; `*compiled` says whether this call compiled it.
  Result<LoadedVariant*, Diagnostics> variant(const Context& context, ShaderAsset& asset, size_t pass,
                                              const variants::VariantKey& key, bool* compiled);
  // For a package without a variant a draw asks for: the .shader it was
  // built from, whose variants `variant` then compiles on demand. Null when
  // the package's variants are all there is: no development layer, strict
  // selection, or no .shader found for it (then `why` says so).
  const std::string* on_demand_source(ShaderAsset& asset, std::string& why);
  // The text the diagnostics of this library's failures point into: the
  // files of a shader that did not load or compile, a scene file a material
  // error is located in. Grows by the files of failures only (one copy of a
  // file per edited version of it that failed).
  SourceMap& report_sources() { return report_; }
  // The development layer, or null when only packages are drawn.
  const ShaderCompiler* compiler() const { return compiler_.get(); }
  void set_compiler(std::shared_ptr<const ShaderCompiler> compiler) { compiler_ = std::move(compiler); }
  // Forgets every shader a file of which changed on disk since it was read
  // (its next use loads it again); returns how many. The GPU must be done
  // with their programs.
  size_t forget_changed();
  // How many shaders forget_changed has forgotten in all: a frame drawn
  // with the library's programs is stale once it grows.
  uint64_t forgotten_total() const { return forgotten_total_; }
  // Starts a render's accounting: load and compile time, loads, misses.
  void begin_render() {
    ++renders_;
    seconds_ = 0;
    loads_ = 0;
    misses_.clear();
    used_.clear();
  }
  double seconds() const { return seconds_; }
  // Every file the shaders this render loaded or used and their compiled
  // variants read, sorted.
  std::vector<std::string> files_read() const;
  size_t loaded() const { return loads_; }  // shaders loaded since begin_render

  // How a draw picks a packaged variant: strict (no exact variant is an
  // error naming the keyword set) or Unity's closest match, each distinct
  // miss recorded once.
  void set_strict_variants(bool strict) { strict_variants_ = strict; }
  bool strict_variants() const { return strict_variants_; }
  void record_miss(const std::string& miss) {
    if (std::find(misses_.begin(), misses_.end(), miss) == misses_.end()) misses_.push_back(miss);
  }
  const std::vector<std::string>& misses() const { return misses_; }

 private:
  // The variant's modules of a package file, checked once each before the driver sees them.
  Result<void, Diagnostics> check_modules(ShaderAsset& asset, const package::PackageVariant& variant);
  Result<std::unique_ptr<LoadedVariant>, Diagnostics> packaged_variant(const Context& context, ShaderAsset& asset,
                                                                       size_t pass, const variants::VariantKey& key,
                                                                       bool* compiled);
  Result<std::unique_ptr<LoadedVariant>, Diagnostics> on_demand_variant(const Context& context, ShaderAsset& asset,
                                                                        size_t pass, const variants::VariantKey& key,
                                                                        bool* compiled);
  Result<std::unique_ptr<LoadedVariant>, Diagnostics> compiled_variant(const Context& context, ShaderAsset& asset,
                                                                       const ir::Shader& shader, SourceMap& sources,
                                                                       size_t selected_pass,
                                                                       const std::vector<std::string>& keywords,
                                                                       bool* compiled);

  void note_read(ShaderAsset& asset, const std::string& path);

  std::shared_ptr<const ShaderCompiler> compiler_;
  std::map<std::string, std::unique_ptr<ShaderAsset>> shaders_;
  double seconds_ = 0;
  size_t loads_ = 0;
  uint64_t renders_ = 0;
  uint64_t forgotten_total_ = 0;
  std::set<std::string> used_;  // paths load() was asked for since begin_render
  bool strict_variants_ = false;
  std::vector<std::string> misses_;
  SourceMap report_;
};

// RenderOptions::shaders (renderer.h): the library kept between renders,
// bound to the Context whose GPU programs it holds.
class ShaderStore {
 public:
  const Context* context = nullptr;
  std::unique_ptr<ShaderLibrary> library;
};

}  // namespace facet::runtime
