// What an engine does with facet's library: load a .shader, look at its
// passes and keyword spaces, compile the variant a material needs, read the
// reflection to bind it, and round-trip the package through its bytes.
// A second part compiles a shader held in memory whose #include is served
// by the engine's own asset system.
//
//   facet_embed path/to/Shader.shader [KEYWORD ...]
#include <facet/compiler.h>
#include <facet/package.h>
#include <facet/variants.h>

#include <iostream>
#include <map>

namespace {

int compile_file(const std::string& path, const std::vector<std::string>& keywords) {
  facet::Compiler compiler;
  facet::CompileOptions options{.keywords = keywords};
  // The results own their messages and the source map they point into.
  facet::OpenedShader loaded = compiler.open_file(path, options);
  if (!loaded.ok()) {
    std::cerr << loaded.messages();
    return 1;
  }
  auto passes = compiler.select_passes(*loaded.shader, options, loaded.diagnostics);
  if (!passes) {
    std::cerr << loaded.messages();
    return 1;
  }
  std::cout << "shader '" << loaded.shader->name << "': " << passes->size() << " pass(es)\n";
  for (const facet::SelectedPass& pass : *passes) {
    auto counts = facet::variants::count_variants(pass.keywords);
    std::cout << "  pass " << pass.pass << " '" << pass.ir.name << "' LightMode=" << pass.ir.tag("LightMode")
              << ": " << counts.full << " variants\n";
  }

  facet::BuildResult built = compiler.build(std::move(loaded), options);
  std::cerr << built.messages();  // warnings survive a success
  if (!built.ok()) return 1;
  const facet::CompiledShader& compiled = *built.compiled;
  for (const facet::package::PackagePass& pass : compiled.package.passes) {
    for (const facet::package::PackageVariant& variant : pass.variants) {
      std::cout << "  variant of '" << pass.name << "' with {";
      for (const std::string& k : variant.keywords) std::cout << " " << k;
      std::cout << " }\n";
      for (const facet::package::PackageStage& stage : variant.stages) {
        const auto& spirv = compiled.package.spirv_blobs[stage.blob];
        std::cout << "    " << facet::stage_name(stage.stage) << ": " << spirv.size() << " SPIR-V words\n";
        for (const facet::UniformBlock& block : stage.reflection.uniform_blocks) {
          std::cout << "      block " << block.name << " set " << block.set << " binding " << block.binding
                    << ", " << block.size << " bytes, " << block.members.size() << " members\n";
        }
      }
    }
  }

  std::vector<uint8_t> bytes = facet::package::write_package(compiled.package);
  facet::Diagnostics read_diags;
  auto back = facet::package::read_package(bytes, read_diags);
  if (!back) {
    std::cerr << facet::render_text(read_diags, built.sources);
    return 1;
  }
  std::cout << "package: " << bytes.size() << " bytes, " << back->spirv_blobs.size()
            << " unique SPIR-V blobs, read back OK\n";
  return 0;
}

// The engine keeps its shader sources in memory (an asset database, a pack file).
int compile_in_memory() {
  const std::map<std::string, std::string> assets = {
      {"engine/Tint.hlsl", "float4 _Tint;\nfloat4 tint(float4 c) { return c * _Tint; }\n"}};
  facet::CompileOptions options;
  options.backend.resolver = [&](const std::string& requested,
                                 const std::string&) -> std::optional<facet::backend::IncludedFile> {
    auto it = assets.find(requested);
    if (it == assets.end()) return std::nullopt;
    return facet::backend::IncludedFile{it->first, it->second};
  };
  facet::Compiler compiler;
  facet::BuildResult built = compiler.build_source("memory/Tinted.shader", R"(Shader "Engine/Tinted" {
  SubShader { Pass {
    CGPROGRAM
    #pragma vertex vert
    #pragma fragment frag
    #include "engine/Tint.hlsl"
    float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
    float4 frag() : SV_Target { return tint(float4(1, 1, 1, 1)); }
    ENDCG
  } }
})", options);
  std::cerr << built.messages();
  if (!built.ok()) return 1;
  const auto& fragment = built.compiled->package.passes.at(0).variants.at(0).stages.at(1).reflection;
  for (const facet::UniformBlock& block : fragment.uniform_blocks) {
    for (const facet::BlockMember& member : block.members) {
      std::cout << "in-memory shader: " << block.name << "." << member.name << " at offset " << member.offset
                << "\n";
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: facet_embed SHADER [KEYWORD ...]\n";
    return 2;
  }
  std::vector<std::string> keywords(argv + 2, argv + argc);
  if (int rc = compile_file(argv[1], keywords); rc != 0) return rc;
  return compile_in_memory();
}
