// Arbitrary bytes as the HLSL of a fixed one-pass ShaderLab wrapper,
// compiled (default variant) through glslang, SPIRV-Tools and reflection:
// the path every shader's code takes. Keep inputs small (-max_len): glslang
// is slow on large ones. The wrapper declares `vert` and `frag` as entry
// points; the seeds define them.
#include "facet/compiler.h"
#include "fuzz_support.h"

namespace {

using namespace facet;

const Compiler& compiler() {
  static const Compiler instance;  // glslang's process initialisation, once
  return instance;
}

constexpr std::string_view kHead =
    "Shader \"Fuzz/Hlsl\" {\n"
    "  SubShader {\n"
    "    Pass {\n"
    "      HLSLPROGRAM\n"
    "      #pragma vertex vert\n"
    "      #pragma fragment frag\n";
constexpr std::string_view kTail =
    "\n"
    "      ENDHLSL\n"
    "    }\n"
    "  }\n"
    "}\n";

CompileOptions fuzz_options() {
  CompileOptions options;
  options.keywords = std::vector<std::string>{};  // the default variant only
  options.max_variants_per_pass = 16;
  options.jobs = 1;
  return options;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const CompileOptions options = fuzz_options();
  static const std::string path = fuzz::TempDir::get().file("fuzz_hlsl.shader");
  std::string text;
  text.reserve(kHead.size() + size + kTail.size());
  text.append(kHead).append(fuzz::as_text(data, size)).append(kTail);
  SourceMap sources;
  Diagnostics diags;
  auto shader = compiler().load_source(path, std::move(text), sources, diags, options);
  if (shader) (void)compiler().compile(*shader, options, sources, diags);
  (void)render_text(diags, sources);
  return 0;
}
