#include "render/probes.h"
#include "render/shaders.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstring>

namespace facet::runtime {
namespace {

// Unity Euler angles of a camera looking through each cube face so that its
// image is the face as Vulkan samples it (cube_direction in sky_sh.h): +X,
// -X, +Y, -Y, +Z, -Z.
constexpr std::array<Vec3, 6> kFaceRotations = {Vec3{0, 90, 0}, Vec3{0, -90, 0}, Vec3{-90, 0, 0},
                                                Vec3{90, 0, 0}, Vec3{0, 0, 0},   Vec3{0, 180, 0}};

glm::vec3 v3(const Vec3& v) { return {v[0], v[1], v[2]}; }

// 1 deep inside the box, falling to 0 at its faces over `blend` units; 0 outside.
float inside_weight(const SceneReflectionProbe& p, const glm::vec3& c) {
  glm::vec3 half = v3(p.size) * 0.5f;
  glm::vec3 depth = half - glm::abs(c - v3(p.position));
  float inside = std::min({depth.x, depth.y, depth.z});
  if (inside < 0) return 0;
  return p.blend_distance > 0 ? std::min(inside / p.blend_distance, 1.0f) : 1.0f;
}

void set_probe(UniformValues& u, const Scene& scene, int probe, int slot, float blend) {
  const std::string name = "unity_SpecCube" + std::to_string(slot);
  u.set_vector(name + "_HDR", 1, 1, 0, 0);
  if (probe < 0) {  // the environment: no box
    u.set_vector(name + "_BoxMin", 0, 0, 0, blend);
    u.set_vector(name + "_BoxMax", 0, 0, 0, 0);
    u.set_vector(name + "_ProbePosition", 0, 0, 0, 0);
    return;
  }
  const SceneReflectionProbe& p = scene.reflection_probes[size_t(probe)];
  glm::vec3 lo = v3(p.position) - v3(p.size) * 0.5f, hi = v3(p.position) + v3(p.size) * 0.5f;
  u.set_vector(name + "_BoxMin", lo.x, lo.y, lo.z, blend);
  u.set_vector(name + "_BoxMax", hi.x, hi.y, hi.z, 0);
  u.set_vector(name + "_ProbePosition", p.position[0], p.position[1], p.position[2], p.box_projection ? 1.0f : 0.0f);
}

}  // namespace

Result<std::vector<CubeMips>, Diagnostics> render_probes(Context& context, const Scene& scene,
                                                         const RenderOptions& options) {
  std::vector<CubeMips> cubes;
  // One library for every face of every probe: each compiles a variant once.
  const std::shared_ptr<ShaderStore> shaders = options.shaders ? options.shaders : make_shader_store();
  for (const SceneReflectionProbe& probe : scene.reflection_probes) {
    Scene seen = scene;
    seen.reflection_probes.clear();
    seen.post.clear();
    seen.tonemap = Tonemap::none;
    seen.camera.projection = Projection::perspective;
    seen.camera.fov = 90;
    seen.camera.near = 0.05f;
    seen.camera.exposure = 1;
    seen.camera.clear_sky = scene.camera.clear_sky || scene.environment || scene.sky;
    RenderOptions face_options;
    face_options.width = face_options.height = probe.resolution;
    face_options.shader_compiler = options.shader_compiler;
    face_options.shaders = shaders;
    face_options.strict_variants = options.strict_variants;
    const uint32_t size = uint32_t(probe.resolution);
    CubeMips cube{size, {std::vector<float>(size_t(size) * size * 6 * 4)}};
    for (size_t face = 0; face < 6; ++face) {
      seen.camera.transform = Transform{.position = probe.position, .rotation = kFaceRotations[face]};
      SourceMap face_sources;
      Diagnostics face_diags;
      Result<RenderedFrame> frame = render_scene(context, seen, face_options, face_sources, face_diags);
      if (!frame) {
        // Located in the store's library's map, which this render's errors point into.
        if (!shaders->library) return unexpected(face_diags);  // no library: nothing was loaded, nothing has a place
        SourceMap& report = shaders->library->report_sources();
        return unexpected(scene_error(report, scene, probe.json_path, DiagId::render_invalid,
                                      fmt::format("rendering the probe's face {}", face),
                                      rebase_diagnostics(face_diags, face_sources, report)));
      }
      float* out = &cube.mips[0][face * size_t(size) * size * 4];
      for (size_t i = 0; i < size_t(size) * size * 4; ++i) out[i] = frame->hdr[i] * (i % 4 == 3 ? 1.0f : probe.intensity);
    }
    build_box_mips(cube);
    cubes.push_back(prefilter_ggx(cube, {}));
  }
  return cubes;
}

ProbeChoice choose_probes(const Scene& scene, const glm::vec3& centre) {
  std::vector<int> holding;
  for (size_t i = 0; i < scene.reflection_probes.size(); ++i) {
    if (inside_weight(scene.reflection_probes[i], centre) > 0) holding.push_back(int(i));
  }
  auto volume = [&](int i) {
    const Vec3& s = scene.reflection_probes[size_t(i)].size;
    return s[0] * s[1] * s[2];
  };
  std::stable_sort(holding.begin(), holding.end(), [&](int a, int b) {
    int ia = scene.reflection_probes[size_t(a)].importance, ib = scene.reflection_probes[size_t(b)].importance;
    return ia != ib ? ia > ib : volume(a) < volume(b);
  });
  ProbeChoice c;
  if (holding.empty()) return c;
  c.probe0 = holding[0];
  const float w0 = inside_weight(scene.reflection_probes[size_t(c.probe0)], centre);
  if (holding.size() == 1) {
    c.blend = w0;  // fades into the environment near its faces
    return c;
  }
  c.probe1 = holding[1];
  const float w1 = inside_weight(scene.reflection_probes[size_t(c.probe1)], centre);
  const bool same_importance =
      scene.reflection_probes[size_t(c.probe0)].importance == scene.reflection_probes[size_t(c.probe1)].importance;
  c.blend = same_importance ? w0 / std::max(w0 + w1, 1e-6f) : w0;
  return c;
}

void add_probe_values(UniformValues& values, const Scene& scene, const ProbeChoice& choice) {
  set_probe(values, scene, choice.probe0, 0, choice.blend);
  set_probe(values, scene, choice.probe1, 1, 0);
}

}  // namespace facet::runtime
