// SPIR-V -> GLSL 450 / ESSL 300 / MSL with SPIRV-Cross. SPIRV-Cross throws;
// cross_compile() is the one place that catches.
#include <fmt/format.h>

#include <spirv_cross/spirv_glsl.hpp>
#include <spirv_cross/spirv_msl.hpp>

#include <algorithm>
#include <exception>
#include <map>
#include <set>

#include "facet/backend.h"

namespace facet::backend {
namespace {

// Combined samplers are named after their texture ("_MainTex"), or
// "<texture>_<sampler>" when one texture is used with several samplers.
void combine_samplers(spirv_cross::CompilerGLSL& compiler) {
  compiler.build_combined_image_samplers();
  std::set<std::string> used;
  for (const auto& remap : compiler.get_combined_image_samplers()) {
    std::string image = compiler.get_name(remap.image_id);
    std::string name = used.insert(image).second ? image : image + "_" + compiler.get_name(remap.sampler_id);
    compiler.set_name(remap.combined_id, name);
  }
}

// OpenGL has no descriptor sets: uniform blocks, storage blocks, textures and
// images each get their own binding numbers 0, 1, ... in (set, binding) order.
void flatten_bindings(spirv_cross::CompilerGLSL& compiler) {
  using spirv_cross::Resource;
  std::map<uint32_t, std::pair<uint32_t, uint32_t>> combined_keys;  // combined id -> image's (set, binding)
  for (const auto& remap : compiler.get_combined_image_samplers()) {
    combined_keys[remap.combined_id] = {compiler.get_decoration(remap.image_id, spv::DecorationDescriptorSet),
                                        compiler.get_decoration(remap.image_id, spv::DecorationBinding)};
  }
  auto key = [&](const Resource& r) {
    auto combined = combined_keys.find(r.id);
    if (combined != combined_keys.end()) return combined->second;
    return std::pair(compiler.get_decoration(r.id, spv::DecorationDescriptorSet),
                     compiler.get_decoration(r.id, spv::DecorationBinding));
  };
  auto number = [&](spirv_cross::SmallVector<Resource> list) {
    std::stable_sort(list.begin(), list.end(), [&](const Resource& a, const Resource& b) { return key(a) < key(b); });
    for (uint32_t i = 0; i < list.size(); ++i) {
      compiler.unset_decoration(list[i].id, spv::DecorationDescriptorSet);
      compiler.set_decoration(list[i].id, spv::DecorationBinding, i);
    }
  };
  spirv_cross::ShaderResources res = compiler.get_shader_resources();
  number(res.uniform_buffers);
  number(res.storage_buffers);
  number(res.sampled_images);
  number(res.storage_images);
}

std::string to_glsl(const std::vector<uint32_t>& spirv, bool es) {
  spirv_cross::CompilerGLSL compiler(spirv);
  spirv_cross::CompilerGLSL::Options options;
  options.version = es ? 300 : 450;
  options.es = es;
  options.vulkan_semantics = false;
  options.enable_420pack_extension = !es;
  options.fragment.default_float_precision = spirv_cross::CompilerGLSL::Options::Highp;
  options.fragment.default_int_precision = spirv_cross::CompilerGLSL::Options::Highp;
  compiler.set_common_options(options);
  combine_samplers(compiler);
  if (!es) flatten_bindings(compiler);
  return compiler.compile();
}

std::string to_msl(const std::vector<uint32_t>& spirv) {
  spirv_cross::CompilerMSL compiler(spirv);
  spirv_cross::CompilerMSL::Options options;
  options.set_msl_version(2, 0);
  compiler.set_msl_options(options);
  return compiler.compile();
}

const char* target_name(CrossTarget target) {
  switch (target) {
    case CrossTarget::glsl450: return "GLSL 450";
    case CrossTarget::essl300: return "ESSL 300";
    case CrossTarget::msl: return "MSL";
  }
  return "?";
}

}  // namespace

Result<std::string> cross_compile(const std::vector<uint32_t>& spirv, Stage stage, CrossTarget target,
                                  Diagnostics& diags) {
  if (target == CrossTarget::essl300 && stage != Stage::vertex && stage != Stage::fragment) {
    diags.add(DiagId::backend_cross_compile_failed, SourceSpan{},
              fmt::format("ESSL 300 has no {} stage", stage_name(stage)));
    return failure("unsupported stage");
  }
  try {
    switch (target) {
      case CrossTarget::glsl450: return to_glsl(spirv, false);
      case CrossTarget::essl300: return to_glsl(spirv, true);
      case CrossTarget::msl: return to_msl(spirv);
    }
  } catch (const std::exception& e) {
    diags.add(DiagId::backend_cross_compile_failed, SourceSpan{},
              fmt::format("cannot translate the {} stage to {}: {}", stage_name(stage), target_name(target), e.what()));
    return failure("cross-compilation failed");
  }
  return failure("unknown target");
}

}  // namespace facet::backend
