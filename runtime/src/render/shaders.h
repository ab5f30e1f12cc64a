// Shaders a scene uses, loaded once each, and their variants compiled on
// first use: one pass and one variant per compile, so a frame costs exactly
// the (pass, variant) pairs its draws need.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "facet/compiler.h"
#include "render/program.h"

namespace facet::runtime {

struct CompiledVariant {
  package::Package package;
  std::unique_ptr<GpuProgram> program;
  std::vector<std::string> keywords;
};

struct ShaderAsset {
  std::string path;
  SourceMap sources;
  ir::Shader shader;
  std::vector<SelectedPass> passes;  // of the SubShader in use; point into `shader`
  int queue = 2000;                  // the SubShader's "Queue" tag
  std::map<std::pair<size_t, variants::VariantKey>, std::unique_ptr<CompiledVariant>> variants;
};

// "Geometry+1" -> 2001, "Transparent" -> 3000, "2450" -> 2450; nullopt if unreadable.

class ShaderLibrary {
 public:
  explicit ShaderLibrary(std::string cache_dir) : cache_dir_(std::move(cache_dir)) {}

  // Errors are the compiler's diagnostics, rendered as text.
  Result<ShaderAsset*, std::string> load(const std::string& path);
  // The variant of pass `pass` (an index into asset.passes) with this key,
  // compiled and on the GPU; `*compiled` says whether this call compiled it.
  Result<CompiledVariant*, std::string> variant(const Context& context, ShaderAsset& asset, size_t pass,
                                                const variants::VariantKey& key, bool* compiled);
  double seconds() const { return seconds_; }
  size_t loaded() const { return shaders_.size(); }

 private:
  Compiler compiler_;
  std::string cache_dir_;
  std::map<std::string, std::unique_ptr<ShaderAsset>> shaders_;
  double seconds_ = 0;
};

}  // namespace facet::runtime
