// Which passes and variants a build compiles (select_passes, select_variants).
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>

#include "facet/compiler.h"
#include "facet/support/text.h"

namespace facet {
namespace {

std::optional<size_t> parse_index(const std::string& text) {
  size_t value = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

bool pass_requested(const ir::Pass& pass, size_t index, const std::vector<std::string>& requested) {
  if (requested.empty()) return true;
  for (const std::string& r : requested) {
    if (auto i = parse_index(r); i && *i == index) return true;
    if (!pass.name.empty() && upper(pass.name) == upper(r)) return true;
  }
  return false;
}

// "Shader/PASSNAME" naming a pass of this same shader. A UsePass naming
// another shader that is still a UsePass here was not found when the shader
// was loaded, which said why (link.h).
const ir::Pass* resolve_use_pass(const ir::Shader& shader, const ir::Pass& use, Diagnostics& diags) {
  auto slash = use.use_pass.rfind('/');
  std::string shader_name = slash == std::string::npos ? "" : use.use_pass.substr(0, slash);
  std::string pass_name = upper(slash == std::string::npos ? use.use_pass : use.use_pass.substr(slash + 1));
  if (shader_name != shader.name) return nullptr;
  for (const ir::SubShader& sub : shader.subshaders) {
    for (const ir::Pass& p : sub.passes) {
      if (p.kind == ir::PassKind::normal && upper(p.name) == pass_name) return &p;
    }
  }
  diags.add(DiagId::driver_usepass_unresolved, use.span,
            fmt::format("UsePass '{}' is not resolved: this shader has no pass named '{}'; the pass is skipped",
                        use.use_pass, use.use_pass.substr(slash + 1)));
  return nullptr;
}

}  // namespace

Result<std::vector<SelectedPass>> Compiler::select_passes(const ir::Shader& shader, const CompileOptions& options,
                                                          Diagnostics& diags) const {
  if (shader.subshaders.empty()) {
    // Unity accepts a shader that only names a Fallback: every draw uses the
    // fallback shader. It has nothing of its own to compile.
    if (shader.fallback) {
      diags.add(DiagId::driver_fallback_only, shader.span,
                fmt::format("shader '{}' has no SubShader; Unity draws it with its Fallback '{}'", shader.name,
                            *shader.fallback));
      return std::vector<SelectedPass>{};
    }
    diags.add(DiagId::driver_no_program, shader.span, fmt::format("shader '{}' has no SubShader", shader.name));
    return failure("no subshader");
  }
  // Every SubShader targets Vulkan-class hardware, so the first one is used.
  const size_t sub_index = 0;
  const ir::SubShader& sub = shader.subshaders[sub_index];
  if (!sub.surface_programs.empty()) {
    diags.add(DiagId::driver_surface_unsupported, sub.surface_programs[0].program.body.span,
              "surface shaders ('#pragma surface') are not supported by this version of facet yet");
    return failure("surface shader");
  }
  std::vector<SelectedPass> selected;
  bool failed = false;
  for (size_t i = 0; i < sub.passes.size(); ++i) {
    const ir::Pass& pass = sub.passes[i];
    if (!pass_requested(pass, i, options.passes)) continue;
    const ir::Pass* source = &pass;
    if (pass.kind == ir::PassKind::grab_pass) {
      diags.add(DiagId::driver_grabpass_skipped, pass.span, "GrabPass has no program to compile; the package records it before the pass that follows it");
      continue;
    }
    if (pass.kind == ir::PassKind::use_pass) {
      source = resolve_use_pass(shader, pass, diags);
      if (!source) continue;
    }
    if (!source->program) continue;
    auto space = variants::build_keyword_space(*source->program, diags);
    if (!space) {
      failed = true;
      continue;
    }
    selected.push_back({sub_index, i, *source, std::move(*space)});
  }
  if (failed) return failure("bad keyword pragmas");
  if (selected.empty() && !options.passes.empty()) {
    std::string names;
    for (size_t i = 0; i < sub.passes.size(); ++i) {
      names += fmt::format("{}{} ('{}')", names.empty() ? "" : ", ", i, sub.passes[i].name);
    }
    diags.add(DiagId::driver_no_such_pass, {}, fmt::format("no pass matches '{}'", fmt::join(options.passes, " ")))
        .note({}, fmt::format("the passes are: {}", names.empty() ? "none" : names));
    return failure("no such pass");
  }
  return selected;
}

namespace {

bool strips_anything(const SelectedPass& pass, const CompileOptions& options) {
  return !pass.keywords.rules.empty() || !options.strip.empty() || options.variant_filter;
}

// The enumerated keys that survive the keyword rules, the filter and the callback.
std::vector<variants::VariantKey> surviving(const SelectedPass& pass, std::vector<variants::VariantKey> keys,
                                            const CompileOptions& options, uint64_t& stripped) {
  if (!strips_anything(pass, options)) return keys;
  std::vector<variants::VariantKey> out;
  for (variants::VariantKey& key : keys) {
    std::vector<std::string> keywords = variants::all_keywords(pass.keywords, key);
    bool keep = !variants::strip_reason(pass.keywords, keywords, options.strip, pass.ir.name, pass.pass);
    if (keep && options.variant_filter) keep = options.variant_filter({pass.ir, pass.pass, keywords});
    if (keep) out.push_back(std::move(key));
  }
  stripped += keys.size() - out.size();
  return out;
}

}  // namespace

Result<variants::VariantSet> Compiler::select_variants(const SelectedPass& pass, const CompileOptions& options,
                                                       Diagnostics& diags) const {
  variants::VariantSet set{.space = pass.keywords};
  variants::EnumerateOptions enumerate{.materials = options.materials,
                                       .drop_unreachable = !options.build_unreachable,
                                       .max_variants = options.max_variants_per_pass == 0
                                                           ? UINT64_MAX
                                                           : options.max_variants_per_pass};
  if (options.keywords) {
    variants::SelectOptions select{.strict = options.strict_selection};
    std::vector<variants::VariantKey> available;
    if (strips_anything(pass, options) || options.materials) {
      auto keys = variants::enumerate(pass.keywords, enumerate, diags);
      FACET_TRY(keys);
      uint64_t not_counted = 0;  // a draw-time pick strips nothing from the build
      available = surviving(pass, std::move(*keys), options, not_counted);
      select.available = &available;
    }
    auto chosen = variants::select_variant(pass.keywords, *options.keywords, {}, select, diags);
    FACET_TRY(chosen);
    set.keys.push_back(chosen->key);
    return set;
  }
  auto keys = variants::enumerate(pass.keywords, enumerate, diags);
  FACET_TRY(keys);
  set.keys = surviving(pass, std::move(*keys), options, set.stripped);
  return set;
}

}  // namespace facet
