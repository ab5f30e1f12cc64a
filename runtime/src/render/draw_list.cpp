#include "render/draw_list.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstring>

#include "facet/variants.h"
#include "render/shadows.h"

namespace facet::runtime {

std::string light_description(const Scene& scene, size_t i) {
  const char* type = scene.lights[i].type == LightType::directional ? "directional"
                     : scene.lights[i].type == LightType::point     ? "point"
                                                                    : "spot";
  return fmt::format("{} ({})", scene.lights[i].json_path, type);
}

Result<GpuMesh, Diagnostics> upload_mesh(const Context& context, const MeshData& data) {
  GpuMesh mesh;
  VkResultOf<Buffer> v = create_buffer(context, data.vertices.size() * sizeof(Vertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  VkResultOf<Buffer> i = create_buffer(context, data.indices.size() * 4, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  if (!v) return unexpected(render_error(describe(v.error()), DiagId::vulkan_failed));
  if (!i) return unexpected(render_error(describe(i.error()), DiagId::vulkan_failed));
  std::memcpy(v->data(), data.vertices.data(), data.vertices.size() * sizeof(Vertex));
  std::memcpy(i->data(), data.indices.data(), data.indices.size() * 4);
  mesh.vertices = std::move(*v);
  mesh.indices = std::move(*i);
  mesh.index_count = uint32_t(data.indices.size());
  mesh.bounds = mesh_bounds(data);
  return mesh;
}

DrawRecord pass_record(const ObjectState& object, size_t p) {
  const ir::Pass& pass = object.shader->passes[p].ir;
  DrawRecord record;
  record.object = object.scene->name.empty() ? object.scene->json_path
                                             : fmt::format("{} ({})", object.scene->json_path, object.scene->name);
  record.object_index = object.index;
  record.shader = object.shader->shader.name;
  record.shader_path = object.shader->path;
  record.pass_index = object.shader->passes[p].pass;
  record.pass_name = pass.name;
  record.pass = pass.name.empty() ? std::to_string(object.shader->passes[p].pass)
                                  : fmt::format("{} {}", object.shader->passes[p].pass, pass.name);
  record.light_mode = pass.tag("LightMode");
  record.queue = object.queue;
  return record;
}

namespace {

std::string light_name(const Scene& scene, size_t i) { return light_description(scene, i); }

std::vector<std::string> fog_keywords(const Scene& scene) {
  switch (scene.fog.mode) {
    case FogMode::linear: return {"FOG_LINEAR"};
    case FogMode::exp: return {"FOG_EXP"};
    case FogMode::exp2: return {"FOG_EXP2"};
    case FogMode::off: break;
  }
  return {};
}

std::string join(const std::vector<std::string>& words) {
  std::string s;
  for (const std::string& w : words) s += (s.empty() ? "" : " ") + w;
  return s.empty() ? "(none)" : s;
}

// How a pass takes part in forward rendering.
enum class Role { once, base, add, vertex, deferred, skip };

// A directional light's receivers read the screen-space mask (screen_shadows.h),
// which holds what the camera depth texture holds: the opaque objects. As in
// Unity, a transparent object (queue > 2500) gets no directional shadows.
bool receives_shadows(const ObjectState& object, const SceneLight& light) {
  return light.type != LightType::directional || object.queue <= 2500;
}

const char* kNoTransparentShadows = "; no shadows: transparent (queue > 2500), and the screen-space shadow mask holds "
                                    "the opaque objects";

bool deferred_mode(const ir::Pass& pass) { return iequals(pass.tag("LightMode"), "Deferred"); }

// Unity's deferred path draws an object into the G-buffer when the camera
// renders deferred, the object is opaque (queue <= 2500) and its shader has
// a Deferred pass; everything else is drawn forward.
bool drawn_deferred(const Scene& scene, const ObjectState& object) {
  if (!scene.camera.deferred || object.queue > 2500 || object.background) return false;
  return std::any_of(object.shader->passes.begin(), object.shader->passes.end(),
                     [](const SelectedPass& p) { return p.ir.kind == ir::PassKind::normal && p.ir.program && deferred_mode(p.ir); });
}

bool forward_mode(const ir::Pass& pass) {
  std::string mode = pass.tag("LightMode");
  return iequals(mode, "ForwardBase") || iequals(mode, "ForwardAdd");
}

// `forward_shader`: the shader has ForwardBase or ForwardAdd passes, which
// Unity's forward path draws instead of its vertex-lit ones.
Role role_of(const ir::Pass& pass, bool forward_shader, bool deferred, std::string& why) {
  if (pass.kind != ir::PassKind::normal || !pass.program) {
    why = pass.kind == ir::PassKind::grab_pass ? "GrabPass is not supported yet" : "UsePass is not supported yet";
    return Role::skip;
  }
  std::string mode = pass.tag("LightMode");
  if (deferred) {
    if (iequals(mode, "Deferred")) return Role::deferred;
    if (iequals(mode, "ForwardBase") || iequals(mode, "ForwardAdd") || iequals(mode, "Vertex") ||
        iequals(mode, "VertexLM") || iequals(mode, "VertexLMRGBM")) {
      why = fmt::format("LightMode {}: the object is drawn deferred (its Deferred pass into the G-buffer)", mode);
      return Role::skip;
    }
  }
  if (mode.empty() || iequals(mode, "Always") || iequals(mode, "SRPDefaultUnlit")) return Role::once;
  if (iequals(mode, "ForwardBase")) return Role::base;
  if (iequals(mode, "ForwardAdd")) return Role::add;
  if (iequals(mode, "Vertex")) {
    if (!forward_shader) return Role::vertex;
    why = "LightMode Vertex: the shader has forward passes, which forward rendering draws instead";
    return Role::skip;
  }
  if (iequals(mode, "VertexLM") || iequals(mode, "VertexLMRGBM")) {
    why = fmt::format("LightMode {}: drawn only for lightmapped objects (facet has no lightmaps)", mode);
    return Role::skip;
  }
  if (iequals(mode, "Deferred")) {
    why = "LightMode Deferred: drawn only when the camera renders deferred, for opaque objects (queue <= 2500)";
    return Role::skip;
  }
  why = iequals(mode, "ShadowCaster") ? "LightMode ShadowCaster: drawn only into shadow maps"
                                      : fmt::format("LightMode {} is not part of forward rendering", mode);
  return Role::skip;
}

}  // namespace

Result<void, Diagnostics> add_draw(const Context& context, const Scene& scene, ShaderLibrary& library,
                                   ObjectState& object, size_t pass_index, const LightValues* light,
                                   const std::vector<std::string>& global, DrawRecord record, DrawListResult& out) {
  ShaderAsset& asset = *object.shader;
  const SelectedPass& pass = asset.passes[pass_index];
  Diagnostics diags;
  variants::SelectOptions select;
  if (asset.package) {  // only the variants built offline exist
    select.available = &asset.available[pass_index];
    select.strict = library.strict_variants();
  }
  Result<variants::Selection> pick =
      variants::select_variant(pass.keywords, object.material.keywords, global, select, diags);
  std::string where = fmt::format("{}: {}: shader '{}' pass {}", scene.path, object.scene->material.json_path,
                                  asset.shader.name, record.pass);
  if (!pick) return unexpected(render_error_in(where, DiagId::variant_missing, diags));
  if (asset.package && !pick->exact) {
    std::vector<std::string> asked = object.material.keywords;
    asked.insert(asked.end(), global.begin(), global.end());
    std::string miss = fmt::format("{}: pass {}: no variant for {{{}}}", asset.path, record.pass, fmt::join(asked, " "));
    std::string no_source;
    if (const std::string* source = library.on_demand_source(asset, no_source)) {
      // The exact variant, compiled from the .shader the package was built from.
      pick = variants::select_variant(pass.keywords, object.material.keywords, global, {}, diags);
      if (!pick) return unexpected(render_error_in(where, DiagId::variant_missing, diags));
      library.record_miss(fmt::format("{}; compiled on demand from {}", miss, *source));
      record.why += fmt::format("; compiled on demand from {} (the package lacks the variant)", *source);
    } else {
      library.record_miss(fmt::format("{}; drawn with Unity's closest match {{{}}}{}", miss,
                                      fmt::join(variants::all_keywords(pass.keywords, pick->key), " "),
                                      no_source.empty() ? "" : " (" + no_source + ")"));
    }
  }
  bool compiled = false;
  Result<LoadedVariant*, Diagnostics> variant = library.variant(context, asset, pass_index, pick->key, &compiled);
  if (!variant) return unexpected(render_error_in(where, DiagId::shader_unavailable, variant.error()));
  if (compiled) {
    ++out.variants_compiled;
    out.compiled.push_back(fmt::format("{} {}: {}", asset.shader.name, record.pass, join((*variant)->keywords)));
  }
  Result<PipelineState> state = resolve_state(pass.ir.state, object.material, diags);
  if (!state) return unexpected(render_error_in(where, DiagId::render_state_property, diags));
  Draw draw;
  draw.object = object.index;
  draw.pass = pass_index;
  draw.light = light;
  draw.variant = *variant;
  draw.state = *state;
  record.keywords = (*variant)->keywords;
  record.exact = pick->exact;
  record.state = describe(*state);
  if (!pick->exact) record.why += "; no exact variant, Unity's closest match";
  if (!pick->unknown_keywords.empty()) record.why += "; ignored (not declared): " + join(pick->unknown_keywords);
  draw.record = std::move(record);
  out.draws.push_back(std::move(draw));
  return {};
}

namespace {

// The textures of the GrabPasses written between the selected pass before
// `p` (or the SubShader's start) and `p`; a package records them per pass.
std::vector<std::string> grab_passes_before(const ShaderAsset& asset, size_t p) {
  if (asset.package) return p < asset.package->passes.size() ? asset.package->passes[p].grab_before : std::vector<std::string>{};
  const SelectedPass& sel = asset.passes[p];
  if (sel.subshader >= asset.shader.subshaders.size()) return {};
  size_t from = p == 0 ? 0 : asset.passes[p - 1].pass + 1;
  return ir::grab_textures(asset.shader.subshaders[sel.subshader], from, sel.pass);
}

struct Builder {
  const Context& context;
  const Scene& scene;
  std::vector<ObjectState>& objects;
  const LightSetup& lights;
  ShaderLibrary& library;
  DrawListResult out;

  Result<void, Diagnostics> add(ObjectState& object, size_t pass_index, const LightValues* light,
                                const std::vector<std::string>& global, DrawRecord record) {
    return add_draw(context, scene, library, object, pass_index, light, global, std::move(record), out);
  }

  Result<void, Diagnostics> vertex_lit_draw(ObjectState& object, size_t p, const std::vector<std::string>& fog,
                                            const std::string& fog_note, DrawRecord record) {
    std::vector<size_t> chosen = vertex_lights(scene, lights, object);
    const LightValues& values = out.draw_lights.emplace_back(vertex_light_values(scene, chosen, lights.view));
    for (size_t i : chosen) record.light += (record.light.empty() ? "" : ", ") + light_name(scene, i);
    record.why = fmt::format("LightMode Vertex: lit per vertex by {} of the scene's lights (at most 8)", chosen.size()) +
                 fog_note;
    return add(object, p, &values, fog, std::move(record));
  }

  // ForwardBase: the main light, and the object's vertex and SH lights.
  Result<void, Diagnostics> base_draw(ObjectState& object, size_t p, const ObjectLights& scheduled,
                                      const std::vector<std::string>& fog, const std::string& fog_note,
                                      DrawRecord record) {
    std::vector<std::string> global = {"DIRECTIONAL", "LIGHTPROBE_SH"};
    global.insert(global.end(), fog.begin(), fog.end());
    const LightValues* light = &lights.none;
    if (lights.main >= 0) {
      light = &lights.lights[size_t(lights.main)];
      record.light = light_name(scene, size_t(lights.main));
      record.why = "ForwardBase: the brightest directional light, ambient as SH" + fog_note;
      const SceneLight& main = scene.lights[size_t(lights.main)];
      if (light->shadowed && receives_shadows(object, main)) {
        std::vector<std::string> shadows = shadow_keywords(main);
        global.insert(global.end(), shadows.begin(), shadows.end());
        record.why += "; its shadows: " + join(shadows);
      } else if (light->shadowed) {
        record.why += kNoTransparentShadows;
      }
    } else {
      record.why = "ForwardBase: no directional light (black light), ambient as SH" + fog_note;
    }
    auto names = [&](const std::vector<size_t>& list) {
      std::string text;
      for (size_t i : list) text += (text.empty() ? "" : ", ") + light_name(scene, i);
      return text;
    };
    std::vector<size_t> unpixeled = scheduled.vertex;
    unpixeled.insert(unpixeled.end(), scheduled.sh.begin(), scheduled.sh.end());
    if (!unpixeled.empty()) {
      std::vector<size_t> unimportant;
      for (size_t i : unpixeled) {
        if (scene.lights[i].render_mode == LightRenderMode::not_important) unimportant.push_back(i);
      }
      record.why += fmt::format("; beyond pixel_light_count {}", scene.pixel_light_count);
      if (!unimportant.empty()) record.why += fmt::format(" or not important ({})", names(unimportant));
    }
    if (!scheduled.vertex.empty()) {
      global.push_back("VERTEXLIGHT_ON");
      record.why += fmt::format(": per vertex (VERTEXLIGHT_ON): {}", names(scheduled.vertex));
    }
    if (!scheduled.sh.empty()) {
      record.why += fmt::format("{} into SH: {}", scheduled.vertex.empty() ? ":" : ";", names(scheduled.sh));
    }
    if (!scheduled.vertex.empty() || !scheduled.sh.empty()) {
      light = &out.draw_lights.emplace_back(
          forward_base_values(*light, scene, lights.ambient, scheduled.vertex, scheduled.sh, object.center));
    }
    return add(object, p, light, global, std::move(record));
  }

  Result<void, Diagnostics> object_draws(ObjectState& object) {
    std::vector<std::string> fog = fog_keywords(scene);
    std::string fog_note = fog.empty() ? "" : fmt::format("; fog {}", fog[0]);
    bool forward_shader = std::any_of(object.shader->passes.begin(), object.shader->passes.end(),
                                      [](const SelectedPass& p) { return forward_mode(p.ir); });
    ObjectLights scheduled = schedule_lights(scene, lights, object);
    const bool deferred = drawn_deferred(scene, object);
    std::vector<std::string> grabs;  // of GrabPasses not yet followed by a draw
    for (size_t p = 0; p < object.shader->passes.size(); ++p) {
      const ir::Pass& pass = object.shader->passes[p].ir;
      std::vector<std::string> before = grab_passes_before(*object.shader, p);
      grabs.insert(grabs.end(), before.begin(), before.end());
      const size_t first_draw = out.draws.size();
      Result<void, Diagnostics> drawn = pass_draws(object, p, pass, scheduled, fog, fog_note, forward_shader, deferred);
      if (!drawn) return drawn;
      if (out.draws.size() > first_draw && !grabs.empty()) {
        Draw& d = out.draws[first_draw];
        d.record.why += fmt::format("; after GrabPass: the screen copied into {}", join(grabs));
        d.grab_before = std::move(grabs);
        grabs.clear();
      }
    }
    return {};
  }

  // The draws of pass `p` of `object`: none (skipped), one, or one per light.
  Result<void, Diagnostics> pass_draws(ObjectState& object, size_t p, const ir::Pass& pass,
                                       const ObjectLights& scheduled, const std::vector<std::string>& fog,
                                       const std::string& fog_note, bool forward_shader, bool deferred) {
    DrawRecord record = pass_record(object, p);
    std::string why;
    Role role = role_of(pass, forward_shader, deferred, why);
    if (role == Role::skip) {
      record.drawn = false;
      record.why = why;
      out.skipped.push_back(record);
      return {};
    }
    if (role == Role::vertex) return vertex_lit_draw(object, p, fog, fog_note, record);
    if (role == Role::once) {
      record.why = "no LightMode: drawn once, without a light" + fog_note;
      return add(object, p, &lights.none, fog, record);
    }
    if (role == Role::base) return base_draw(object, p, scheduled, fog, fog_note, record);
    if (role == Role::deferred) return gbuffer_draw(object, p, record);
    return additive_draws(object, p, scheduled, fog, fog_note, record);
  }

  // Deferred: the surface into the G-buffer, and what it gives off by itself
  // (ambient as SH, reflections, emission) into the light buffer; every
  // light is added later from the G-buffer. Unity's HDR camera: the light
  // buffer is the RGBA16F colour target (UNITY_HDR_ON). No fog: Unity's
  // deferred path leaves fog to an image effect.
  Result<void, Diagnostics> gbuffer_draw(ObjectState& object, size_t p, DrawRecord record) {
    record.why = "Deferred: the G-buffer (diffuse, specular and smoothness, normal) and ambient, reflections and "
                 "emission into the light buffer; the lights are added from the G-buffer";
    const size_t before = out.draws.size();
    FACET_TRY(add(object, p, &lights.none, {"LIGHTPROBE_SH", "UNITY_HDR_ON"}, std::move(record)));
    out.gbuffer.push_back(std::move(out.draws[before]));
    out.draws.erase(out.draws.begin() + long(before));
    return {};
  }

  // ForwardAdd: one draw per further pixel light.
  Result<void, Diagnostics> additive_draws(ObjectState& object, size_t p, const ObjectLights& scheduled,
                                           const std::vector<std::string>& fog, const std::string& fog_note,
                                           DrawRecord record) {
    const std::vector<size_t>& extra = scheduled.pixel;
    if (extra.empty()) {
      record.drawn = false;
      record.why = "ForwardAdd: no further per-pixel light reaches the object";
      out.skipped.push_back(record);
    }
    for (size_t k = 0; k < extra.size(); ++k) {
      const LightValues& light = lights.lights[extra[k]];
      std::vector<std::string> global = {light.keyword};
      global.insert(global.end(), fog.begin(), fog.end());
      DrawRecord add_record = record;
      add_record.additive = true;
      add_record.light = light_name(scene, extra[k]);
      bool important = scene.lights[extra[k]].render_mode == LightRenderMode::important;
      add_record.why = fmt::format("ForwardAdd: further pixel light {} of {}{}, additive", k + 1, extra.size(),
                                   important ? " (important: always a pixel light)" : "") +
                       fog_note;
      if (light.shadowed && receives_shadows(object, scene.lights[extra[k]])) {
        std::vector<std::string> shadows = shadow_keywords(scene.lights[extra[k]]);
        global.insert(global.end(), shadows.begin(), shadows.end());
        add_record.why += "; its shadows: " + join(shadows);
      } else if (light.shadowed) {
        add_record.why += kNoTransparentShadows;
      }
      if (light.cookie) add_record.why += fmt::format("; cookie {}.cookie as _LightTexture0", scene.lights[extra[k]].json_path);
      FACET_TRY(add(object, p, &light, global, add_record));
    }
    return {};
  }
};

}  // namespace

LightSetup setup_lights(const Scene& scene, const glm::mat4& view, const UnitySh& ambient) {
  LightSetup setup;
  setup.view = view;
  setup.ambient = ambient;
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    setup.lights.push_back(light_values(scene.lights[i]));
    // ForwardBase has no cookie variant (multi_compile_fwdbase declares only
    // DIRECTIONAL), so a directional light with a cookie is drawn additively.
    if (scene.lights[i].type != LightType::directional || scene.lights[i].cookie ||
        scene.lights[i].render_mode == LightRenderMode::not_important) {
      continue;
    }
    if (setup.main < 0 || setup.lights[i].brightness > setup.lights[size_t(setup.main)].brightness) {
      setup.main = int(i);
    }
  }
  return setup;
}

namespace {

// The lights that reach `object`, directional ones first, then by Unity's
// importance (brightness falling off with distance over range); lights out
// of range of the object's bounds are culled, as Unity culls them.
std::vector<size_t> ranked_lights(const Scene& scene, const LightSetup& setup, const ObjectState& object,
                                  bool include_main) {
  struct Candidate {
    size_t index;
    bool directional;
    float importance;
  };
  std::vector<Candidate> candidates;
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    if (int(i) == setup.main && !include_main) continue;
    const SceneLight& light = scene.lights[i];
    const LightValues& values = setup.lights[i];
    if (values.brightness <= 0) continue;
    if (light.type == LightType::directional) {
      candidates.push_back({i, true, values.brightness});
      continue;
    }
    float d = glm::length(values.position - object.center);
    if (d >= light.range + object.radius) continue;
    float r = d / light.range;
    candidates.push_back({i, false, values.brightness / (1 + 25 * r * r)});
  }
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    if (a.directional != b.directional) return a.directional;
    return a.importance > b.importance;
  });
  std::vector<size_t> out;
  for (const Candidate& c : candidates) out.push_back(c.index);
  return out;
}

}  // namespace

ObjectLights schedule_lights(const Scene& scene, const LightSetup& setup, const ObjectState& object) {
  std::vector<size_t> ranked = ranked_lights(scene, setup, object, false);
  auto mode = [&](size_t i) { return scene.lights[i].render_mode; };
  long important = std::count_if(ranked.begin(), ranked.end(), [&](size_t i) { return mode(i) == LightRenderMode::important; });
  long automatic = std::max(0L, long(scene.pixel_light_count) - (setup.main >= 0 ? 1 : 0) - important);
  ObjectLights out;
  for (size_t i : ranked) {
    bool pixel = mode(i) == LightRenderMode::important || (mode(i) == LightRenderMode::automatic && automatic > 0);
    if (pixel) {
      if (mode(i) == LightRenderMode::automatic) --automatic;
      out.pixel.push_back(i);
    } else if (scene.lights[i].type == LightType::point && out.vertex.size() < 4) {
      out.vertex.push_back(i);
    } else {
      out.sh.push_back(i);
    }
  }
  return out;
}

std::vector<size_t> vertex_lights(const Scene& scene, const LightSetup& setup, const ObjectState& object) {
  std::vector<size_t> out = ranked_lights(scene, setup, object, true);
  if (out.size() > 8) out.resize(8);
  return out;
}

Result<DrawListResult, Diagnostics> build_draws(const Context& context, const Scene& scene,
                                                std::vector<ObjectState>& objects, const LightSetup& lights,
                                                ShaderLibrary& library) {
  Builder builder{context, scene, objects, lights, library, {}};
  for (ObjectState& object : objects) FACET_TRY(builder.object_draws(object));
  std::stable_sort(builder.out.gbuffer.begin(), builder.out.gbuffer.end(), [&](const Draw& a, const Draw& b) {
    const ObjectState& oa = objects[a.object];
    const ObjectState& ob = objects[b.object];
    if (oa.queue != ob.queue) return oa.queue < ob.queue;
    return oa.distance < ob.distance;
  });
  // Queues in order; opaque front to back, transparent (queue > 2500) back to
  // front; an object's passes stay together and in shader order.
  std::stable_sort(builder.out.draws.begin(), builder.out.draws.end(), [&](const Draw& a, const Draw& b) {
    const ObjectState& oa = objects[a.object];
    const ObjectState& ob = objects[b.object];
    if (oa.queue != ob.queue) return oa.queue < ob.queue;
    if (a.object == b.object) return false;
    if (oa.distance != ob.distance) return oa.queue > 2500 ? oa.distance > ob.distance : oa.distance < ob.distance;
    return a.object < b.object;
  });
  return std::move(builder.out);
}

}  // namespace facet::runtime
