#include "directive.h"

#include <fmt/format.h>

#include <array>
#include <string_view>

namespace facet::surface {
namespace {

// Options that change nothing in facet, and why (lightmaps, deferred
// shading and the like do not exist here).
constexpr std::array<std::pair<std::string_view, std::string_view>, 9> kIgnored = {{
    {"nolightmap", "facet has no lightmaps"},
    {"nodynlightmap", "facet has no lightmaps"},
    {"nodirlightmap", "facet has no lightmaps"},
    {"nometa", "facet generates no Meta pass"},
    {"halfasview", "the view direction is always per pixel"},
    {"interpolateview", "the view direction is always per pixel"},
    {"noshadowmask", "facet has no shadow masks"},
    {"dithercrossfade", "facet has no LOD cross-fade"},
    {"approxview", "the view direction is always per pixel"},
}};

bool value_option(std::string_view arg, std::string_view name, std::string& value) {
  if (!arg.starts_with(name) || arg.size() <= name.size() || arg[name.size()] != ':') return false;
  value = std::string(arg.substr(name.size() + 1));
  return true;
}

bool flag_option(std::string_view arg, Directive& d) {
  static constexpr std::pair<std::string_view, bool Directive::*> kFlags[] = {
      {"keepalpha", &Directive::keep_alpha},   {"addshadow", &Directive::add_shadow},
      {"fullforwardshadows", &Directive::full_forward_shadows},
      {"noshadow", &Directive::no_shadow},     {"noambient", &Directive::no_ambient},
      {"nofog", &Directive::no_fog},           {"noforwardadd", &Directive::no_forward_add},
      {"noinstancing", &Directive::no_instancing}, {"novertexlights", &Directive::no_vertex_lights}};
  for (auto [name, member] : kFlags) {
    if (arg == name) {
      d.*member = true;
      return true;
    }
  }
  return false;
}

}  // namespace

Result<Directive> parse_directive(const ir::Pragma& pragma, Diagnostics& diags) {
  Directive d;
  d.span = pragma.span;
  if (pragma.args.size() < 2) {
    diags.add(DiagId::surface_bad_directive, pragma.span, "'#pragma surface' needs a surface function and a lighting model")
        .note({}, "write '#pragma surface surf Standard' (or Lambert, BlinnPhong, StandardSpecular, or your own model)");
    return failure("bad surface pragma");
  }
  d.surface_function = pragma.args[0];
  d.model = pragma.args[1];
  for (size_t i = 2; i < pragma.args.size(); ++i) {
    const std::string& arg = pragma.args[i];
    std::string value;
    if (flag_option(arg, d)) continue;
    if (value_option(arg, "vertex", d.vertex_function) || value_option(arg, "finalcolor", d.final_color_function) ||
        value_option(arg, "alphatest", d.alpha_test_property) ||
        value_option(arg, "tessellate", d.tessellate_function) || value_option(arg, "tessphong", d.tess_phong)) {
      continue;
    }
    if (arg == "alpha" || value_option(arg, "alpha", value)) {
      if (arg == "alpha" || value == "auto") {
        d.alpha = d.physically_based() ? AlphaMode::premultiply : AlphaMode::fade;
      } else if (value == "blend" || value == "fade") {
        d.alpha = AlphaMode::fade;
      } else if (value == "premul") {
        d.alpha = AlphaMode::premultiply;
      } else {
        diags.add(DiagId::surface_bad_directive, pragma.span, fmt::format("unknown alpha mode '{}'", value))
            .note({}, "use alpha, alpha:auto, alpha:blend, alpha:fade or alpha:premul");
        return failure("bad alpha mode");
      }
      continue;
    }
    if (value_option(arg, "decal", value)) {
      if (value != "add" && value != "blend") {
        diags.add(DiagId::surface_bad_directive, pragma.span, fmt::format("unknown decal mode '{}'", value))
            .note({}, "use decal:add or decal:blend");
        return failure("bad decal mode");
      }
      d.decal = value == "add" ? DecalMode::add : DecalMode::blend;
      continue;
    }
    if (value_option(arg, "exclude_path", value)) {
      if (value == "forward") d.exclude_forward = true;
      else if (value == "deferred") d.exclude_deferred = true;
      else diags.add(DiagId::surface_option_ignored, pragma.span,
                     fmt::format("'{}' changes nothing: facet has no legacy light pre-pass path", arg));
      continue;
    }
    bool ignored = false;
    for (auto [name, why] : kIgnored) {
      if (arg == name) {
        diags.add(DiagId::surface_option_ignored, pragma.span, fmt::format("'{}' is accepted and changes nothing: {}", arg, why));
        ignored = true;
      }
    }
    if (!ignored) {
      diags.add(DiagId::surface_unknown_option, pragma.span, fmt::format("unknown surface shader option '{}' is ignored", arg));
    }
  }
  if (!d.tess_phong.empty() && !d.tessellated()) {
    diags.add(DiagId::surface_bad_directive, pragma.span,
              fmt::format("'tessphong:{}' needs 'tessellate:<function>': Phong tessellation smooths the "
                          "vertices that tessellation makes",
                          d.tess_phong));
    return failure("tessphong without tessellate");
  }
  // No instancing variants: the instance ID would have to pass through the
  // hull and domain stages (docs/surface-shaders.md).
  if (d.tessellated()) d.no_instancing = true;
  if (d.exclude_forward) {
    diags.add(DiagId::surface_bad_directive, pragma.span,
              "'exclude_path:forward' is not supported: facet draws transparent objects and forward cameras with "
              "the forward passes, and a surface shader always has them");
    return failure("no path");
  }
  return d;
}

}  // namespace facet::surface
