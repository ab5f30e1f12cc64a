#include "render/scene_frame.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>

#include "facet/runtime/gltf.h"
#include "facet/runtime/vulkan_context.h"
#include "render/background.h"
#include "render/instancing.h"
#include "render/probes.h"

namespace facet::runtime {
namespace {

struct Loader {
  const Context& context;
  const Scene& scene;
  ShaderLibrary& library;
  Resources& resources;
  std::map<std::string, std::unique_ptr<GpuMesh>>& meshes;
  std::vector<std::shared_ptr<const MeshData>>& mesh_sources;
  uint64_t& meshes_loaded;

  // An engine's MeshData: every index must name a vertex.
  Result<const MeshData*, Diagnostics> engine_mesh(const SceneObject& object) {
    const MeshData& data = *object.mesh_data;
    auto bad = [&](const std::string& why) {
      return unexpected(
          render_error(fmt::format("{}: {}.mesh_data: {}", scene.path, object.json_path, why), DiagId::mesh_invalid));
    };
    if (data.vertices.empty() || data.indices.empty()) return bad("no vertices or no indices");
    if (data.indices.size() % 3 != 0) return bad(fmt::format("{} indices: not whole triangles", data.indices.size()));
    for (size_t i = 0; i < data.indices.size(); ++i) {
      if (data.indices[i] >= data.vertices.size()) {
        return bad(fmt::format("index {} is {}, but there are {} vertices", i, data.indices[i], data.vertices.size()));
      }
    }
    mesh_sources.push_back(object.mesh_data);
    return &data;
  }

  Result<GpuMesh*, Diagnostics> mesh(const SceneObject& object) {
    std::string key = object.mesh_data ? fmt::format("memory:{}", static_cast<const void*>(object.mesh_data.get()))
                      : object.gltf_material ? fmt::format("{}#{}", object.mesh, *object.gltf_material)
                                             : object.mesh;
    if (auto it = meshes.find(key); it != meshes.end()) return it->second.get();
    std::optional<MeshData> loaded;
    const MeshData* data = nullptr;
    if (object.mesh_data) {
      Result<const MeshData*, Diagnostics> given = engine_mesh(object);
      if (!given) return unexpected(given.error());
      data = *given;
    } else {
      Diagnostics mesh_diags;
      if (object.builtin_mesh) {
        loaded = builtin_mesh(object.mesh);
      } else if (is_gltf_path(object.mesh)) {
        if (std::optional<GltfModel> model = load_gltf(object.mesh, mesh_diags)) {
          loaded = merge_gltf_parts(*model, object.gltf_material);
        }
      } else {
        loaded = load_obj(object.mesh, mesh_diags);
      }
      if (!loaded) {
        // The loader's one error, said at the scene's value ("objects[2].mesh: a.obj:4:7: ...").
        std::string why = mesh_diags.all().empty() ? "the mesh does not load" : mesh_diags.all()[0].message;
        return unexpected(
            scene_error(library.report_sources(), scene, object.json_path + ".mesh", DiagId::mesh_invalid, why));
      }
      data = &*loaded;
    }
    Result<GpuMesh, Diagnostics> gpu = upload_mesh(context, *data);
    if (!gpu) return unexpected(gpu.error());
    ++meshes_loaded;
    auto& slot = meshes[key];
    slot = std::make_unique<GpuMesh>(std::move(*gpu));
    return slot.get();
  }

  Result<void, Diagnostics> texel_sizes(Material& material, const SceneObject& object) {
    for (const auto& [name, ref] : material.textures) {
      Result<const LoadedTexture*, std::string> t = resources.texture(ref);
      if (!t) {
        return unexpected(scene_error(library.report_sources(), scene,
                                      object.json_path + ".material.properties." + name, DiagId::texture_invalid,
                                      t.error()));
      }
      float w = float((*t)->width), h = float((*t)->height);
      material.uniforms.set_vector(name + "_TexelSize", 1 / w, 1 / h, w, h);
    }
    return {};
  }

  Result<ObjectState, Diagnostics> object(size_t index, const CameraMatrices& camera) {
    const SceneObject& o = scene.objects[index];
    ObjectState s;
    s.index = index;
    s.scene = &o;
    Result<ShaderAsset*, Diagnostics> shader = library.load(o.material.shader);
    if (!shader) {
      return unexpected(scene_error(library.report_sources(), scene, o.json_path + ".material.shader",
                                    DiagId::shader_unavailable, "the shader does not compile", shader.error()));
    }
    s.shader = *shader;
    Diagnostics material_diags;
    Result<Material> material =
        make_material(s.shader->shader, o.material, scene.path, library.report_sources(), material_diags);
    if (!material) return unexpected(material_diags);
    s.material = std::move(*material);
    FACET_TRY(texel_sizes(s.material, o));
    s.queue = o.material.queue.value_or(s.shader->queue);
    Result<GpuMesh*, Diagnostics> m = mesh(o);
    if (!m) return unexpected(m.error());
    s.mesh = *m;
    s.model = transform_matrix(o.transform);
    s.model_values = true;
    s.mirrored = glm::determinant(glm::mat3(s.model)) < 0;
    const Bounds& b = s.mesh->bounds;
    s.center = glm::vec3(s.model * glm::vec4(b.center[0], b.center[1], b.center[2], 1));
    float scale = std::max({std::abs(o.transform.scale[0]), std::abs(o.transform.scale[1]), std::abs(o.transform.scale[2])});
    s.radius = b.radius * scale;
    s.distance = glm::length(s.center - camera.position);
    return s;
  }
};

// The objects of `frame.scene` with their materials, meshes and probes.
Result<void, Diagnostics> load_objects(SceneFrame& frame) {
  Loader loader{frame.context,    *frame.scene,       *frame.library,
                frame.resources,  frame.meshes,       frame.mesh_sources,
                frame.meshes_loaded};
  frame.objects.clear();
  frame.objects.reserve(frame.scene->objects.size());
  for (size_t i = 0; i < frame.scene->objects.size(); ++i) {
    Result<ObjectState, Diagnostics> o = loader.object(i, frame.camera);
    if (!o) return unexpected(o.error());
    if (!frame.probe_images.empty()) {
      ProbeChoice choice = choose_probes(*frame.scene, o->center);
      add_probe_values(o->draw, *frame.scene, choice);
      for (int slot : {0, 1}) {
        int probe = slot == 0 ? choice.probe0 : choice.probe1;
        o->probes[size_t(slot)] = probe >= 0 ? frame.probe_images[size_t(probe)] : nullptr;
      }
    }
    frame.objects.push_back(std::move(*o));
  }
  return {};
}

// An engine's meshes (SceneObject::mesh_data) that no object draws any
// more: freed, so that a loop giving new geometry every frame does not
// accumulate the old. The GPU is done with them (each frame is waited for).
void forget_unused_engine_meshes(SceneFrame& frame) {
  std::set<const GpuMesh*> drawn;
  for (const ObjectState& o : frame.objects) drawn.insert(o.mesh);
  std::erase_if(frame.meshes, [&](const auto& entry) {
    return entry.first.starts_with("memory:") && !drawn.contains(entry.second.get());
  });
  std::set<const MeshData*> used;
  for (const SceneObject& o : frame.scene->objects) used.insert(o.mesh_data.get());
  std::erase_if(frame.mesh_sources, [&](const std::shared_ptr<const MeshData>& m) { return !used.contains(m.get()); });
}

// The lights, their shadow views, and the draw list of the loaded objects.
Result<void, Diagnostics> build_lists(SceneFrame& frame) {
  const Scene& scene = *frame.scene;
  frame.lights = setup_lights(scene, frame.camera.view, frame.environment->ambient);
  frame.shadow_views.clear();
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    if (std::optional<ShadowView> v =
            shadow_view(scene, i, frame.objects, frame.camera, float(frame.width) / float(frame.height))) {
      add_shadow_values(frame.lights.lights[i], scene.lights[i], *v, scene.shadow_resolution);
      frame.shadow_views.push_back(*v);
    }
  }
  if (Result<void, std::string> cookies = frame.resources.load_cookies(scene); !cookies) {
    return unexpected(render_error(cookies.error(), DiagId::texture_invalid));
  }
  Result<DrawListResult, Diagnostics> list =
      build_draws(frame.context, scene, frame.objects, frame.lights, *frame.library);
  if (!list) return unexpected(list.error());
  frame.list = std::move(*list);
  frame.instanced_away = merge_instanced_draws(frame.list.draws, frame.objects);
  return {};
}

// The pipelines of `draws` in `render_pass`, one a draw.
Result<std::vector<VkPipeline>, Diagnostics> pipelines_for(SceneFrame& frame, const std::vector<Draw>& draws,
                                                           const std::vector<ObjectState>& owners,
                                                           VkRenderPass render_pass, uint32_t color_targets) {
  std::vector<VkPipeline> out;
  out.reserve(draws.size());
  for (const Draw& d : draws) {
    bool created = false;
    Result<VkPipeline, std::string> p = get_pipeline(frame.context, *d.variant->program, d.state, owners[d.object].mirrored,
                                                     render_pass, frame.pipeline_cache, &created, color_targets);
    if (!p) return unexpected(render_error(fmt::format("{}: {}: {}", frame.scene->path, d.record.object, p.error())));
    out.push_back(*p);
    frame.pipelines_created += created;
  }
  return out;
}

bool samples_depth_texture(const std::vector<Draw>& draws) {
  return std::any_of(draws.begin(), draws.end(), [](const Draw& d) { return samples(d, "_CameraDepthTexture"); });
}

// What update_frame cannot give the draws of its new list: the passes that
// were not prepared.
std::string pass_blocker(const SceneFrame& frame) {
  if (!frame.list.gbuffer.empty()) return "objects are drawn into the G-buffer";
  if (samples_depth_texture(frame.list.draws)) return "a draw samples the camera depth texture";
  if (!screen_shadowed_lights({&frame.list.draws}).empty()) return "a draw reads screen-space shadows";
  for (const Draw& d : frame.list.draws) {
    if (!d.grab_before.empty()) return "a draw has a GrabPass";
  }
  return "";
}

// The engine image's layout change around the blit from `result` (in
// TRANSFER_SRC_OPTIMAL) into it.
void copy_to_target(VkCommandBuffer commands, const Image& result, uint32_t width, uint32_t height,
                    const ImageTarget& target) {
  VkImageMemoryBarrier to_dst{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  to_dst.srcAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  to_dst.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  to_dst.oldLayout = target.layout;
  to_dst.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  to_dst.srcQueueFamilyIndex = to_dst.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  to_dst.image = target.image;
  to_dst.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                       nullptr, 1, &to_dst);
  VkImageBlit blit{};
  blit.srcSubresource = blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.srcOffsets[1] = {int32_t(width), int32_t(height), 1};
  blit.dstOffsets[1] = {int32_t(target.width), int32_t(target.height), 1};
  const bool scaled = width != target.width || height != target.height;
  vkCmdBlitImage(commands, result.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target.image,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, scaled ? VK_FILTER_LINEAR : VK_FILTER_NEAREST);
  VkImageMemoryBarrier to_final = to_dst;
  to_final.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  to_final.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  to_final.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  to_final.newLayout = target.final_layout;
  vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr, 0,
                       nullptr, 1, &to_final);
}

}  // namespace

std::string target_problem(const Context& context, const ImageTarget& target) {
  if (!target.image) return "the target has no image";
  if (target.width == 0 || target.height == 0) return "the target's size is 0";
  if (target.final_layout == VK_IMAGE_LAYOUT_UNDEFINED || target.final_layout == VK_IMAGE_LAYOUT_PREINITIALIZED) {
    return "the target's final layout must be one an image can be left in";
  }
  VkFormatProperties p{};
  vkGetPhysicalDeviceFormatProperties(context.physical_device(), target.format, &p);
  if (is_depth_format(target.format)) return "the target's format is a depth format: it needs a colour one";
  if (!(p.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT)) {
    return fmt::format("the device cannot blit into the target's format (VkFormat {})", int(target.format));
  }
  return "";
}

SceneFrame::~SceneFrame() {
  vkDeviceWaitIdle(context.device());
  if (pipeline_cache) vkDestroyPipelineCache(context.device(), pipeline_cache, nullptr);
}

Result<std::unique_ptr<SceneFrame>, Diagnostics> prepare_frame(Context& context, const Scene& scene_in,
                                                               ShaderLibrary& library, const FrameSetup& setup) {
  auto owned = std::make_unique<SceneFrame>(context);
  SceneFrame& frame = *owned;
  if (setup.keep_scene) frame.kept_scene = scene_in;
  frame.scene = setup.keep_scene ? &*frame.kept_scene : &scene_in;
  const Scene& scene = *frame.scene;
  frame.width = setup.width;
  frame.height = setup.height;
  frame.library = &library;
  // Probes first: each renders the scene (through render_scene) before this
  // frame takes the shader library.
  std::vector<CubeMips> probe_cubes;
  if (!scene.reflection_probes.empty()) {
    Result<std::vector<CubeMips>, Diagnostics> cubes = render_probes(context, scene, setup.probe_options);
    if (!cubes) return unexpected(cubes.error());
    probe_cubes = std::move(*cubes);
  }
  library.begin_render();
  frame.resources.keep_pixels(setup.capture != nullptr);
  frame.camera = camera_matrices(scene.camera, frame.width, frame.height);
  Result<EnvironmentLighting, std::string> environment = environment_lighting(scene);
  if (!environment) return unexpected(render_error(environment.error()));
  frame.environment = std::move(*environment);
  if (Result<const Image*, std::string> cube = frame.resources.environment_cube(frame.environment->cube); !cube) {
    return unexpected(render_error("cannot create the environment cube: " + cube.error(), DiagId::vulkan_failed));
  }
  frame.frame_values = frame_uniforms(scene, frame.camera, frame.width, frame.height, frame.environment->ambient);
  for (const CubeMips& cube : probe_cubes) {
    Result<const Image*, std::string> image = frame.resources.add_probe(cube);
    if (!image) {
      return unexpected(
          render_error("cannot create a reflection probe's cube: " + image.error(), DiagId::vulkan_failed));
    }
    frame.probe_images.push_back(*image);
  }
  FACET_TRY(load_objects(frame));
  FACET_TRY(build_lists(frame));
  if (!scene.post.empty() || scene.camera.clear_sky) {
    Result<GpuMesh, Diagnostics> q = upload_mesh(context, *builtin_mesh("quad"));
    if (!q) return unexpected(q.error());
    frame.quad = std::make_unique<GpuMesh>(std::move(*q));
  }
  if (scene.camera.clear_sky) {
    FACET_TRY(add_sky_background(context, scene, library, frame.quad.get(), &frame.lights.none, frame.sky_source,
                                 frame.objects, frame.list));
  }
  if (!scene.post.empty()) {
    auto chain = build_post_chain(context, scene, library, frame.resources, frame.quad.get(), &frame.lights.none,
                                  frame.width, frame.height);
    if (!chain) return unexpected(chain.error());
    frame.post = std::move(*chain);
  }
  // The deferred path's light pass; without an object drawn deferred the
  // frame is a forward one.
  if (scene.camera.deferred && !frame.list.gbuffer.empty()) {
    auto built = build_deferred_lights(context, scene, library, frame.lights, frame.camera);
    if (!built) return unexpected(built.error());
    frame.deferred = std::move(*built);
  }
  // Unity draws the sky behind the opaque objects at the far plane; the
  // deferred ones are in the depth before the sky, so it is tested there
  // (its draw is given depth 1 by its viewport, see record_frame).
  for (Draw& d : frame.list.draws) {
    if (!frame.deferred || !frame.objects[d.object].background) continue;
    d.state.depth_test = true;
    d.state.ztest = VK_COMPARE_OP_LESS_OR_EQUAL;
    d.state.zwrite = false;
    d.record.state = describe(d.state) + " (at the far plane: behind the deferred objects)";
  }
  // The camera depth texture is the depth buffer itself, kept when an image
  // effect samples it (as the deferred light pass samples it), through its
  // depth-only view (Image::sample_view).
  frame.depth_sampled = frame.post && samples_depth_texture(frame.post->list.draws);
  const bool depth_readable = frame.depth_sampled || frame.deferred;
  // After the deferred passes the forward part continues on their colour and depth.
  const PassEnds last_part{.load = frame.deferred != nullptr, .sampled = frame.post != nullptr,
                           .depth_sampled = frame.depth_sampled};
  FACET_TRY(make_scene_targets(context, uint32_t(frame.width), uint32_t(frame.height), frame.post != nullptr,
                               depth_readable, last_part, frame.targets));
  if (frame.post) FACET_TRY(make_post_targets(context, frame.post_targets, frame.width, frame.height));
  if (frame.deferred) {
    FACET_TRY(make_deferred_targets(context, frame.targets.color, frame.targets.depth, uint32_t(frame.width),
                                    uint32_t(frame.height), frame.gbuffer));
  }
  VkPipelineCacheCreateInfo cache_info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
  if (VkResult r = vkCreatePipelineCache(context.device(), &cache_info, nullptr, &frame.pipeline_cache); r != VK_SUCCESS) {
    frame.pipeline_cache = VK_NULL_HANDLE;  // undefined after a failure; the destructor destroys what is not null
    return unexpected(
        render_error(fmt::format("cannot create the pipeline cache (VkResult {})", int(r)), DiagId::vulkan_failed));
  }
  Result<std::vector<VkPipeline>, Diagnostics> made =
      pipelines_for(frame, frame.list.draws, frame.objects, frame.targets.render_pass, 1);
  if (!made) return unexpected(made.error());
  frame.pipelines = std::move(*made);
  if (frame.deferred) {
    made = pipelines_for(frame, frame.list.gbuffer, frame.objects, frame.gbuffer.gbuffer_pass, kGBufferTargets);
    if (!made) return unexpected(made.error());
    frame.gbuffer_pipelines = std::move(*made);
    made = pipelines_for(frame, frame.deferred->list.draws, frame.deferred->screen.objects, frame.gbuffer.light_pass, 1);
    if (!made) return unexpected(made.error());
    frame.light_pipelines = std::move(*made);
  }
  Result<GrabPlan, Diagnostics> grab_plan =
      plan_grabs(context, scene, frame.list.draws, uint32_t(frame.width), uint32_t(frame.height));
  if (!grab_plan) return unexpected(grab_plan.error());
  frame.grabs = std::move(*grab_plan);
  if (!frame.grabs.points.empty()) {
    if (setup.capture) return unexpected(render_error(scene.path + ": a frame capture does not cover GrabPass"));
    PassEnds first{.load = frame.deferred != nullptr, .to_grab = true}, middle{.load = true, .to_grab = true},
        last = last_part;
    last.load = true;
    for (auto [ends, out] : {std::pair{first, &frame.targets.first_part}, {middle, &frame.targets.middle_part},
                             {last, &frame.targets.last_part}}) {
      Result<VkRenderPass, Diagnostics> part = make_render_pass(context.device(), frame.targets.depth_format, ends);
      if (!part) return unexpected(part.error());
      *out = *part;
    }
  }
  // The maps some drawn variant samples: forward receivers', and the deferred light pass's.
  std::vector<const std::vector<Draw>*> receivers = {&frame.list.draws};
  if (frame.deferred) receivers.push_back(&frame.deferred->list.draws);
  FACET_TRY(prepare_shadow_maps(context, scene, frame.objects, frame.lights, frame.shadow_views, receivers, library,
                                frame.pipeline_cache, frame.shadows, frame.pipelines_created));
  // The directional lights whose receivers read a screen-space mask.
  std::vector<Draw> no_draws;
  const std::vector<const LightValues*> screen_lights =
      screen_shadowed_lights({&frame.list.draws, frame.deferred ? &frame.deferred->list.draws : &no_draws});
  // Objects that sample _CameraDepthTexture get Unity's depth texture: the
  // opaque objects' ShadowCaster passes from the camera, before the scene;
  // the screen-space shadow pass reads it too.
  if (!screen_lights.empty() || samples_depth_texture(frame.list.draws)) {
    FACET_TRY(prepare_camera_depth(context, scene, frame.objects, frame.lights.none, frame.camera, uint32_t(frame.width),
                                   uint32_t(frame.height), library, frame.pipeline_cache, frame.shadows,
                                   frame.pipelines_created));
  }
  FACET_TRY(prepare_screen_shadows(context, scene, library, frame.camera, screen_lights, uint32_t(frame.width),
                                   uint32_t(frame.height), frame.pipeline_cache, frame.screen_shadows,
                                   frame.pipelines_created));
  if (setup.capture && !frame.shadows.maps.empty()) {
    return unexpected(
        render_error(scene.path + ": a frame capture does not cover shadow maps or the camera depth texture"));
  }
  if (frame.post) {
    made = pipelines_for(frame, frame.post->list.draws, frame.post->steps, frame.post_targets.render_pass, 1);
    if (!made) return unexpected(made.error());
    frame.post_pipelines = std::move(*made);
  }
  frame.binder.instance_owners = &frame.objects;
  frame.binder.shadows = &frame.shadows;
  frame.binder.screen_shadows = &frame.screen_shadows;
  if (!frame.shadows.maps.empty() || frame.deferred) {
    Result<VkSampler, std::string> sampler = frame.resources.point_sampler();
    if (!sampler) return unexpected(render_error(sampler.error()));
    frame.binder.point_sampler = *sampler;
  }
  if (setup.capture) {
    *setup.capture = FrameCapture{};
    setup.capture->width = uint32_t(frame.width);
    setup.capture->height = uint32_t(frame.height);
    setup.capture->depth_format = frame.targets.depth_format;
    setup.capture->vertex_stride = sizeof(Vertex);
    frame.capture.emplace(*setup.capture, frame.resources);
    frame.capture_out = setup.capture;
  }
  VkResultOf<Buffer> readback = create_buffer(context, VkDeviceSize(frame.width) * frame.height * 8,
                                              VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  if (!readback) return unexpected(render_error(describe(readback.error()), DiagId::vulkan_failed));
  frame.readback = std::move(*readback);
  return owned;
}

std::string update_blocker(const SceneFrame& frame, const Scene& scene, int width, int height) {
  const Scene& was = *frame.scene;
  if (width != frame.width || height != frame.height) return "the image size changed";
  if (frame.capture) return "the prepared frame was captured";
  if (!frame.shadows.maps.empty() || !frame.screen_shadows.list.draws.empty()) return "the frame has shadows";
  if (frame.deferred || frame.post || !frame.grabs.points.empty() || frame.quad) {
    return "the frame has a deferred pass, image effects, GrabPasses or a sky background";
  }
  if (!scene.reflection_probes.empty() || !frame.probe_images.empty()) return "reflection probes";
  if (!scene.post.empty() || scene.camera.clear_sky || scene.camera.deferred) {
    return "image effects, a sky background or the deferred path";
  }
  if (scene.environment != was.environment || scene.sky != was.sky || scene.ambient != was.ambient ||
      scene.ambient_given != was.ambient_given) {
    return "the environment changed";
  }
  for (const SceneLight& light : scene.lights) {
    if (light.shadows != ShadowMode::none) return "a light casts shadows";
  }
  // The sky's sun lights the ambient and the environment cube, made when
  // the frame was prepared.
  if (scene.sky && scene.sky->sun) {
    const size_t sun = size_t(scene.sky->sun->light);
    if (sun >= scene.lights.size() || sun >= was.lights.size() || !(scene.lights[sun] == was.lights[sun])) {
      return "the sky's sun changed";
    }
  }
  return "";
}

Result<std::string, Diagnostics> update_frame(SceneFrame& frame, const Scene& scene) {
  frame.kept_scene = scene;
  frame.scene = &*frame.kept_scene;
  frame.binder.restart();
  frame.pipelines_created = 0;
  frame.meshes_loaded = 0;
  frame.library->begin_render();
  frame.camera = camera_matrices(frame.scene->camera, frame.width, frame.height);
  // Replaced, not assigned: restart() dropped every pointer into the old values.
  frame.frame_values = frame_uniforms(*frame.scene, frame.camera, frame.width, frame.height, frame.environment->ambient);
  FACET_TRY(load_objects(frame));
  forget_unused_engine_meshes(frame);
  FACET_TRY(build_lists(frame));
  if (std::string blocker = pass_blocker(frame); !blocker.empty()) return blocker;
  Result<std::vector<VkPipeline>, Diagnostics> made =
      pipelines_for(frame, frame.list.draws, frame.objects, frame.targets.render_pass, 1);
  if (!made) return unexpected(made.error());
  frame.pipelines = std::move(*made);
  return std::string();
}

void refresh_frame_values(SceneFrame& frame, const Scene& scene) {
  if (frame.kept_scene) frame.kept_scene->time = scene.time;
  frame.frame_values.assign(per_frame_uniforms(scene, frame.camera, frame.width, frame.height));
}

Result<void, Diagnostics> record_frame(SceneFrame& frame, VkCommandBuffer commands, bool capturing,
                                       const FrameOutput& output, RenderStats& stats) {
  // The frame's parts under the names the recording uses.
  std::vector<ObjectState>& objects = frame.objects;
  DrawListResult* list = &frame.list;
  UniformValues& frame_values = frame.frame_values;
  ScreenShadows& screen_shadows = frame.screen_shadows;
  DeferredLights* deferred = frame.deferred.get();
  DeferredTargets& gbuffer = frame.gbuffer;
  PostChain* post = frame.post.get();
  PostTargets& targets = frame.post_targets;
  const GpuMesh* quad = frame.quad.get();
  GrabPlan& grabs = frame.grabs;
  const SceneTargets& fo = frame.targets;
  const Image* color = &frame.targets.color;
  const Image* depth_image = &frame.targets.depth;
  const std::vector<VkPipeline>& pipelines = frame.pipelines;
  const std::vector<VkPipeline>& gbuffer_pipelines = frame.gbuffer_pipelines;
  const std::vector<VkPipeline>& light_pipelines = frame.light_pipelines;
  const std::vector<VkPipeline>& post_pipelines = frame.post_pipelines;
  const Buffer* readback = &*frame.readback;
  const bool depth_sampled = frame.depth_sampled;
  VkQueryPool queries = frame.context.timestamp_pool();
  std::optional<Diagnostics> failed;
  frame.binder.refresh();
  if (queries) {
    vkCmdResetQueryPool(commands, queries, 0, 2);
    vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, queries, 0);
  }
  glm::vec3 clear = linear_color({frame.scene->camera.clear_color[0], frame.scene->camera.clear_color[1], frame.scene->camera.clear_color[2]});
  if (capturing) frame.capture_out->clear_color = {clear.r, clear.g, clear.b, frame.scene->camera.clear_color[3]};
  Result<uint64_t, Diagnostics> shadow_triangles = record_shadow_maps(
      commands, frame.shadows, frame.objects,
      [&](VkCommandBuffer c, const Draw& d, const UniformValues& light_frame) {
        return frame.binder.bind(c, d, frame.objects[d.object], light_frame);
      },
      frame_values);
  if (!shadow_triangles) return unexpected(shadow_triangles.error());
  stats.triangles += *shadow_triangles;
  VkViewport viewport{0, 0, float(frame.width), float(frame.height), 0, 1};
  VkRect2D scissor{{0, 0}, {uint32_t(frame.width), uint32_t(frame.height)}};
  // Binds `mesh` (unless it is bound already) and draws all of it, `instances` times.
  const GpuMesh* bound_mesh = nullptr;
  auto draw_mesh = [&](const GpuMesh& mesh, uint32_t instances = 1) {
    if (bound_mesh != &mesh) {
      VkBuffer vb = mesh.vertices.handle();
      VkDeviceSize offset = 0;
      vkCmdBindVertexBuffers(commands, 0, 1, &vb, &offset);
      vkCmdBindIndexBuffer(commands, mesh.indices.handle(), 0, VK_INDEX_TYPE_UINT32);
      bound_mesh = &mesh;
    }
    vkCmdDrawIndexed(commands, mesh.index_count, instances, 0, 0, 0);
    stats.triangles += uint64_t(mesh.index_count / 3) * instances;
  };
  // Draws `draws` [first, last) with `pipelines` in a render pass already begun.
  auto draw_all = [&](const std::vector<Draw>& draws, const std::vector<VkPipeline>& draw_pipelines,
                      const std::vector<ObjectState>& owners, size_t first = 0, size_t last = SIZE_MAX) {
    vkCmdSetViewport(commands, 0, 1, &viewport);
    vkCmdSetScissor(commands, 0, 1, &scissor);
    for (size_t i = first; i < std::min(last, draws.size()) && !failed; ++i) {
      const Draw& d = draws[i];
      const ObjectState& object = owners[d.object];
      vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, draw_pipelines[i]);
      if (Result<void, Diagnostics> bound = frame.binder.bind(commands, d, object, frame_values); !bound) {
        failed = bound.error();
        break;
      }
      draw_mesh(*object.mesh);
    }
  };
  for (size_t i = 0; i < screen_shadows.list.draws.size() && !failed; ++i) {
    VkRenderPassBeginInfo mask{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    mask.renderPass = screen_shadows.render_pass;
    mask.framebuffer = screen_shadows.framebuffers[i];
    mask.renderArea = {{0, 0}, {uint32_t(frame.width), uint32_t(frame.height)}};
    VkClearValue lit{};
    lit.color = {{1, 1, 1, 1}};
    mask.clearValueCount = 1;
    mask.pClearValues = &lit;
    vkCmdBeginRenderPass(commands, &mask, VK_SUBPASS_CONTENTS_INLINE);
    frame.binder.overrides.clear();
    draw_all(screen_shadows.list.draws, screen_shadows.pipelines, screen_shadows.screen.objects, i, i + 1);
    vkCmdEndRenderPass(commands);
  }
  if (deferred) {
    glm::vec3 clear_rgb = linear_color({frame.scene->camera.clear_color[0], frame.scene->camera.clear_color[1], frame.scene->camera.clear_color[2]});
    std::array<VkClearValue, kGBufferTargets + 1> gclears{};
    gclears[3].color = {{clear_rgb.r, clear_rgb.g, clear_rgb.b, frame.scene->camera.clear_color[3]}};
    gclears[4].depthStencil = {1.0f, 0};
    VkRenderPassBeginInfo g{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    g.renderPass = gbuffer.gbuffer_pass;
    g.framebuffer = gbuffer.gbuffer_framebuffer;
    g.renderArea = {{0, 0}, {uint32_t(frame.width), uint32_t(frame.height)}};
    g.clearValueCount = uint32_t(gclears.size());
    g.pClearValues = gclears.data();
    vkCmdBeginRenderPass(commands, &g, VK_SUBPASS_CONTENTS_INLINE);
    frame.binder.overrides.clear();
    draw_all(list->gbuffer, gbuffer_pipelines, objects);
    vkCmdEndRenderPass(commands);
    VkRenderPassBeginInfo l = g;
    l.renderPass = gbuffer.light_pass;
    l.framebuffer = gbuffer.light_framebuffer;
    l.clearValueCount = 0;
    l.pClearValues = nullptr;
    vkCmdBeginRenderPass(commands, &l, VK_SUBPASS_CONTENTS_INLINE);
    frame.binder.overrides = gbuffer_textures(gbuffer, *depth_image);
    draw_all(deferred->list.draws, light_pipelines, deferred->screen.objects);
    vkCmdEndRenderPass(commands);
    transition(commands, *depth_image, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
               VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
  }
  VkClearValue clears[2]{};
  clears[0].color = {{clear.r, clear.g, clear.b, frame.scene->camera.clear_color[3]}};
  clears[1].depthStencil = {1.0f, 0};
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = grabs.points.empty() ? fo.render_pass : fo.first_part;
  begin.framebuffer = fo.framebuffer;
  begin.renderArea = {{0, 0}, {uint32_t(frame.width), uint32_t(frame.height)}};
  begin.clearValueCount = 2;
  begin.pClearValues = clears;
  vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
  vkCmdSetViewport(commands, 0, 1, &viewport);
  vkCmdSetScissor(commands, 0, 1, &scissor);
  frame.binder.overrides.clear();
  for (auto& [name, image] : grabs.images) frame.binder.overrides[name] = &image;
  std::map<std::string, bool> grabbed;
  size_t next_grab = 0;
  for (size_t i = 0; i < list->draws.size() && !failed; ++i) {
    const Draw& d = list->draws[i];
    const ObjectState& object = objects[d.object];
    if (next_grab < grabs.points.size() && grabs.points[next_grab].draw == i) {
      vkCmdEndRenderPass(commands);
      record_grab(commands, *color, grabs.points[next_grab], grabs, grabbed);
      stats.grabs += grabs.points[next_grab].names.size();
      ++next_grab;
      VkRenderPassBeginInfo part = begin;
      part.renderPass = next_grab < grabs.points.size() ? fo.middle_part : fo.last_part;
      part.clearValueCount = 0;
      part.pClearValues = nullptr;
      vkCmdBeginRenderPass(commands, &part, VK_SUBPASS_CONTENTS_INLINE);
      vkCmdSetViewport(commands, 0, 1, &viewport);
      vkCmdSetScissor(commands, 0, 1, &scissor);
    }
    if (deferred && object.background) {
      VkViewport far_plane = viewport;
      far_plane.minDepth = far_plane.maxDepth = 1;
      vkCmdSetViewport(commands, 0, 1, &far_plane);
    }
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines[i]);
    std::optional<CapturedDraw> captured;
    if (capturing) {
      captured = CapturedDraw{frame.capture->program(*d.variant->program), frame.capture->mesh(*object.mesh), d.state, object.mirrored};
      frame.binder.capture = &*frame.capture;
    }
    if (Result<void, Diagnostics> bound =
            frame.binder.bind(commands, d, object, frame_values, captured ? &*captured : nullptr);
        !bound) {
      failed = bound.error();
      break;
    }
    const uint32_t instances = uint32_t(std::max<size_t>(1, d.instances.size()));
    if (captured) {
      captured->instances = instances;
      frame.capture_out->draws.push_back(std::move(*captured));
    }
    draw_mesh(*object.mesh, instances);
    if (deferred && object.background) vkCmdSetViewport(commands, 0, 1, &viewport);
  }
  vkCmdEndRenderPass(commands);
  const Image* result = &*color;
  for (size_t i = 0; post && i < post->list.draws.size() && !failed; ++i) {
    VkRenderPassBeginInfo step{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    step.renderPass = targets.render_pass;
    step.framebuffer = targets.framebuffers[i % 2];
    step.renderArea = begin.renderArea;
    vkCmdBeginRenderPass(commands, &step, VK_SUBPASS_CONTENTS_INLINE);
    vkCmdSetViewport(commands, 0, 1, &viewport);
    vkCmdSetScissor(commands, 0, 1, &scissor);
    frame.binder.overrides = {{"_MainTex", result}};
    if (depth_sampled) frame.binder.overrides["_CameraDepthTexture"] = &*depth_image;
    frame.binder.point_sampler = targets.point_sampler;
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, post_pipelines[i]);
    if (Result<void, Diagnostics> bound =
            frame.binder.bind(commands, post->list.draws[i], post->steps[i], frame_values);
        !bound) {
      failed = bound.error();
    } else {
      draw_mesh(*quad);
    }
    vkCmdEndRenderPass(commands);
    result = &targets.images[i % 2];
  }
  if (post) transition(commands, *result, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  if (queries) vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queries, 1);
  if (output.target) copy_to_target(commands, *result, uint32_t(frame.width), uint32_t(frame.height), *output.target);
  if (output.read_back) {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {uint32_t(frame.width), uint32_t(frame.height), 1};
    vkCmdCopyImageToBuffer(commands, result->handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback->handle(), 1,
                           &region);
    VkMemoryBarrier host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &host, 0, nullptr,
                         0, nullptr);
  }
  if (failed) return unexpected(*failed);
  return {};
}

void collect_records(const SceneFrame& frame, RenderedFrame& out, bool records, bool compiled) {
  for (const auto& map : frame.shadows.maps) {
    for (const Draw& d : map->casters.draws) if (records) out.draws.push_back(d.record);
    (map->light ? out.stats.shadow_draws : out.stats.depth_texture_draws) += map->casters.draws.size();
  }
  out.stats.shadow_maps = frame.shadows.light_maps();
  for (const Draw& d : frame.screen_shadows.list.draws) if (records) out.draws.push_back(d.record);
  if (compiled) out.compiled.insert(out.compiled.end(), frame.screen_shadows.list.compiled.begin(), frame.screen_shadows.list.compiled.end());
  if (compiled) out.stats.variants_compiled += frame.screen_shadows.list.variants_compiled;
  out.stats.screen_shadow_masks = frame.screen_shadows.list.draws.size();
  for (const Draw& d : frame.list.gbuffer) if (records) out.draws.push_back(d.record);
  if (frame.deferred) {
    for (const Draw& d : frame.deferred->list.draws) if (records) out.draws.push_back(d.record);
    if (compiled) out.compiled.insert(out.compiled.end(), frame.deferred->list.compiled.begin(), frame.deferred->list.compiled.end());
    if (compiled) out.stats.variants_compiled += frame.deferred->list.variants_compiled;
    out.stats.deferred_lights = frame.deferred->list.draws.size();
  }
  out.stats.gbuffer_draws = frame.list.gbuffer.size();
  for (const Draw& d : frame.list.draws) {
    out.stats.additive_draws += d.record.additive;
    out.stats.instanced_draws += d.instances.size() > 1;
    if (records) out.draws.push_back(d.record);
    for (const DrawRecord& r : d.instance_records) if (records) out.draws.push_back(r);
  }
  out.stats.draws = frame.list.draws.size() + out.stats.shadow_draws + out.stats.depth_texture_draws +
                      out.stats.gbuffer_draws + out.stats.deferred_lights + out.stats.screen_shadow_masks;
  if (compiled) out.compiled.insert(out.compiled.end(), frame.list.compiled.begin(), frame.list.compiled.end());
  if (compiled) out.stats.variants_compiled += frame.list.variants_compiled;
  if (frame.post) {
    for (const Draw& d : frame.post->list.draws) if (records) out.draws.push_back(d.record);
    out.stats.draws += frame.post->list.draws.size();
    if (compiled) out.compiled.insert(out.compiled.end(), frame.post->list.compiled.begin(), frame.post->list.compiled.end());
    if (compiled) out.stats.variants_compiled += frame.post->list.variants_compiled;
  }
  for (const auto& map : frame.shadows.maps) {  // compiled last: after the draws that sample them
    if (compiled) out.compiled.insert(out.compiled.end(), map->casters.compiled.begin(), map->casters.compiled.end());
    if (compiled) out.stats.variants_compiled += map->casters.variants_compiled;
  }
  for (const DrawRecord& r : frame.list.skipped) if (records) out.draws.push_back(r);
  for (const auto& map : frame.shadows.maps) {
    for (const DrawRecord& r : map->casters.skipped) if (records) out.draws.push_back(r);
  }
}

}  // namespace facet::runtime
