// The back end: one program + stage + keyword list -> SPIR-V (glslang),
// validated (spirv-val), optimised (spirv-opt), cross-compiled (SPIRV-Cross)
// and reflected.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "facet/compiled_variant.h"
#include "facet/diagnostics.h"
#include "facet/ir.h"
#include "facet/program_analysis.h"
#include "facet/reflection.h"
#include "facet/result.h"
#include "facet/source.h"
#include "facet/stage.h"

namespace facet::backend {

// The binding model (docs/binding-model.md): descriptor sets by update rate.
// The stdlib declares its cbuffers and textures with explicit register(x, spaceN);
// everything a program declares without a space lands in kMaterialSet.
inline constexpr uint32_t kFrameSet = 0;     // camera, time, fog, environment: cbuffer FacetPerFrame
inline constexpr uint32_t kLightSet = 1;     // the pass's light: cbuffer FacetPerLight, light textures
inline constexpr uint32_t kMaterialSet = 2;  // "$Globals" at binding 0, then textures/cbuffers in declaration order
inline constexpr uint32_t kDrawSet = 3;      // the object: cbuffer FacetPerDraw
// The block that holds a program's loose uniforms (`float4 _Color;`).
inline constexpr const char* kGlobalsBlock = "$Globals";

enum class OptLevel : uint8_t { none, size, performance };  // -O0, -Os, -O
enum class TargetEnv : uint8_t { vulkan1_1, vulkan1_2, opengl4_5 };
enum class CrossTarget : uint8_t { glsl450, essl300, msl };

// An included file found by a resolver: its canonical path and text.
struct IncludedFile {
  std::string path;
  std::string text;
};

// Finds `requested` for an #include in `includer` (a path). nullopt: not found.
using IncludeResolver =
    std::function<std::optional<IncludedFile>(const std::string& requested, const std::string& includer)>;

// The Unity version facet's stdlib follows: Unity 2019.4.
inline constexpr int kDefaultUnityVersion = 201940;

// What one program's compile may take (docs/cli.md, "Input limits"); a
// compile that would exceed one ends in a located error. 0: no limit.
struct InputLimits {
  uint64_t max_includes = 4096;                       // #include directives followed, per program (--max-includes)
  uint64_t max_include_bytes = uint64_t(64) << 20;    // their bytes together, per program (--max-include-bytes)
  uint64_t max_preprocessed_bytes = uint64_t(64) << 20;  // the text after macro expansion (--max-preprocessed-bytes)
  uint64_t max_unroll = 4096;   // iterations of one [unroll] loop (--max-unroll)
  uint32_t time_limit_s = 60;   // wall time of one stage's compile; then the process ends, exit 1 (--time-limit)
};

// Any one included file: as for .shader files, 64 MiB (not an option).
inline constexpr uint64_t kMaxIncludeFileBytes = uint64_t(64) << 20;

struct BackendOptions {
  OptLevel opt = OptLevel::performance;
  TargetEnv target = TargetEnv::vulkan1_1;
  bool debug_info = false;                // -g
  std::vector<std::string> include_dirs;  // -I, searched after the includer's folder
  std::vector<std::pair<std::string, std::string>> defines;  // -D NAME[=VALUE]
  std::string stdlib_dir;                 // searched last
  // UNITY_VERSION as Unity defines it: 2019.4 -> 201940 (facetc --unity-version).
  int unity_version = kDefaultUnityVersion;
  // When set, used instead of the file system (in-memory compiles).
  IncludeResolver resolver;
  InputLimits limits;
  // compile_hlsl_compute only: HLSL `half` and `min16float` are 16-bit floats
  // (float16_t, SPIR-V capability Float16; glslang's EShMsgHlslEnable16BitTypes)
  // and FACET_16BIT_TYPES is defined. The kernel then runs only on a device
  // with shaderFloat16 (runtime::Context::shader_float16). Off: half is a
  // 32-bit float, as in Unity's Vulkan back end.
  bool hlsl_16bit_types = false;
};

// Owns glslang's process initialisation for its lifetime (one per process is
// enough; several are safe). Calls that share a SourceMap must not overlap.
//
//   backend::Backend backend;
//   Diagnostics diags;
//   auto fs = backend.compile(shader, program, Stage::fragment, {"FOG_EXP2"},
//                             {.opt = backend::OptLevel::performance}, sources, diags);
//   if (!fs) return;                        // diags say why, at .shader positions
//   auto glsl = backend::cross_compile(fs->spirv, Stage::fragment, backend::CrossTarget::glsl450, diags);
//   nlohmann::json j = fs->reflection;     // facet/reflection_json.h
class IncludeScanCache;
class CrashIsolation;

// Which text Backend::source_text gives: one stage of one variant.
struct SourceRequest {
  Stage stage = Stage::vertex;
  std::vector<std::string> keywords;  // the variant's keywords that the stage sees
  bool preprocess = true;             // false: the assembled text, before glslang's preprocessor
};

struct SourceText {
  std::string text;
  std::vector<std::string> included_files;  // every file opened, sorted; empty when not preprocessed
};

class Backend {
 public:
  Backend();
  ~Backend();
  Backend(const Backend&) = delete;
  Backend& operator=(const Backend&) = delete;

  // The text glslang would see for this stage and keywords (prelude, defines,
  // #line-mapped program), after preprocessing when the request says so.
  Result<SourceText> source_text(const ir::Shader& shader, const ir::Program& program, const SourceRequest& request,
                                 const BackendOptions& options, SourceMap& sources, Diagnostics& diags) const;

  // Compiles one stage of one variant. Errors are mapped to .shader positions.
  Result<CompiledVariant> compile(const ir::Shader& shader, const ir::Program& program, Stage stage,
                                const std::vector<std::string>& keywords, const BackendOptions& options,
                                SourceMap& sources, Diagnostics& diags) const;

  // Parses `program` as its fragment stage would be parsed (prelude, includes,
  // `keywords` and `extra_defines` defined) and reads the AST
  // (facet/program_analysis.h); nothing is compiled to SPIR-V. Parse errors are
  // reported at .shader positions.
  Result<ProgramAnalysis> analyze_program(const ir::Shader& shader, const ir::Program& program,
                                          const std::vector<std::string>& keywords, const BackendOptions& options,
                                          SourceMap& sources, Diagnostics& diags) const;

 private:
  // The scans of included texts, shared by every program this Backend
  // preprocesses or compiles (include_scan.h).
  std::shared_ptr<IncludeScanCache> scan_cache_;
  // Where glslang parses HLSL: a helper process forked when the Backend is
  // made, whose children die of glslang's crashes instead of the compiler
  // (crash_isolation.h).
  std::unique_ptr<CrashIsolation> isolation_;
};

// Compiles a self-contained HLSL compute shader (DX9 compatibility, as for
// programs; #include resolved through `options`, the stdlib searched last) to
// legalised, optimised and validated SPIR-V. Not tied to a .shader file:
// diagnostics name the line of `source` (as "<compute>:N") or of the include.
Result<std::vector<uint32_t>> compile_hlsl_compute(const std::string& source, const std::string& entry,
                                                   const BackendOptions& options, Diagnostics& diags);

// Code written for float, rewritten for half precision (half_precision.cpp):
// every float type name (float, float2..4, floatNxM) becomes the half one and
// every floating literal gets the half suffix `h` ("0.5" -> "0.5h", "1e-4f" ->
// "1e-4h"); comments, strings, integers and line breaks stay as they are, so
// diagnostics keep their lines. Why a rewrite: with hlsl_16bit_types, glslang
// keeps unsuffixed literals 32-bit and converts no float to half implicitly,
// so `half a = 0.5 * b;` does not compile; the stdlib stays written for float.
std::string to_half_precision(std::string_view hlsl);

// A BackendOptions::resolver for 16-bit kernels: `#include "X"` is read from
// `stdlib_dir` and returned through to_half_precision, except FacetHalf.hlsl
// (the half overloads of the intrinsics: glslang's HLSL intrinsics take and
// return 32-bit floats only), which is returned as written. nullopt when the
// file is not there.
IncludeResolver half_precision_stdlib(const std::string& stdlib_dir);

// The stdlib folder used when BackendOptions::stdlib_dir is empty: $FACET_STDLIB_DIR,
// else the source tree's stdlib/ (a build tree), else the installed one.
std::string default_stdlib_dir();

Result<std::string> cross_compile(const std::vector<uint32_t>& spirv, Stage stage, CrossTarget target,
                                  Diagnostics& diags);
std::string disassemble(const std::vector<uint32_t>& spirv);
// spirv-val; false and a diagnostic when invalid.
bool validate(const std::vector<uint32_t>& spirv, TargetEnv target, Diagnostics& diags);

}  // namespace facet::backend
