#include "variants/shortcuts.h"


#include "facet/variants.h"

namespace facet::variants {
namespace {

struct ShortcutDef {
  std::string_view name;
  ShortcutSets sets;
};

// The order is the documented one (docs/variants.md) and the order of
// known_shortcuts(), which error messages list.
const std::vector<ShortcutDef>& shortcut_table() {
  static const std::vector<ShortcutDef> table = [] {
    const std::vector<std::string> lights = {"POINT", "DIRECTIONAL", "SPOT", "POINT_COOKIE",
                                             "DIRECTIONAL_COOKIE"};
    return std::vector<ShortcutDef>{
        {"multi_compile_fwdbase", {{"DIRECTIONAL"}, {"", "LIGHTPROBE_SH"}, {"", "SHADOWS_SCREEN"}}},
        {"multi_compile_fwdadd", {lights}},
        {"multi_compile_fwdadd_fullshadows",
         {lights, {"", "SHADOWS_DEPTH", "SHADOWS_SCREEN", "SHADOWS_CUBE"}, {"", "SHADOWS_SOFT"}}},
        {"multi_compile_shadowcaster", {{"SHADOWS_DEPTH", "SHADOWS_CUBE"}}},
        // Unity's alpha-blended ForwardBase: no shadow keywords.
        {"multi_compile_fwdbasealpha", {{"DIRECTIONAL"}, {"", "LIGHTPROBE_SH"}}},
        // The deferred light pass: the light types and their shadows.
        {"multi_compile_lightpass",
         {lights, {"", "SHADOWS_DEPTH", "SHADOWS_SCREEN", "SHADOWS_CUBE"}, {"", "SHADOWS_SOFT"}}},
        // The screen-space shadow collector: cascade selection and count.
        {"multi_compile_shadowcollector", {{"", "SHADOWS_SPLIT_SPHERES"}, {"", "SHADOWS_SINGLE_CASCADE"}}},
        // The deferred G-buffer pass: HDR target and light probes.
        {"multi_compile_prepassfinal", {{"", "UNITY_HDR_ON"}, {"", "LIGHTPROBE_SH"}}},
        {"multi_compile_fog", {{"", "FOG_LINEAR", "FOG_EXP", "FOG_EXP2"}}},
        {"multi_compile_instancing", {{"", "INSTANCING_ON"}}},
        {"multi_compile_particles", {{"", "SOFTPARTICLES_ON"}}},
    };
  }();
  return table;
}

struct ModifierDef {
  std::string_view name;
  std::vector<std::string> removes;
};

const std::vector<ModifierDef>& modifier_table() {
  static const std::vector<ModifierDef> table = {
      {"noshadow", {"SHADOWS_SCREEN", "SHADOWS_DEPTH", "SHADOWS_CUBE", "SHADOWS_SOFT"}},
      // Unity's lightmap and shadowmask keywords are never produced by facet's
      // shortcuts, so these are accepted (generated surface code uses them)
      // and remove nothing.
      {"nolightmap", {}},
      {"nodynlightmap", {}},
      {"nodirlightmap", {}},
      {"noshadowmask", {}},
      // Unity's ForwardBase vertex lights and light probe proxy volumes are
      // not keywords of facet's shortcuts either.
      {"novertexlight", {}},
      {"nolppv", {}},
  };
  return table;
}

}  // namespace

std::optional<ShortcutSets> expand_shortcut(std::string_view name) {
  for (const ShortcutDef& def : shortcut_table()) {
    if (def.name == name) return def.sets;
  }
  return std::nullopt;
}

std::optional<std::vector<std::string>> modifier_removals(std::string_view modifier) {
  for (const ModifierDef& def : modifier_table()) {
    if (def.name == modifier) return def.removes;
  }
  return std::nullopt;
}

std::vector<std::string> known_modifiers() {
  std::vector<std::string> names;
  for (const ModifierDef& def : modifier_table()) names.emplace_back(def.name);
  return names;
}

std::vector<std::string> known_shortcuts() {
  std::vector<std::string> names;
  for (const ShortcutDef& def : shortcut_table()) names.emplace_back(def.name);
  return names;
}

}  // namespace facet::variants
