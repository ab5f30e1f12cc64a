// Scenes as plain data, read from the JSON format of docs/scene-format.md.
// Reading checks the JSON's shape (types, counts, enum words, ranges) and
// names the JSON path of anything wrong; what depends on the shaders
// (property names and types) is checked when the renderer binds materials,
// with the same kind of path.
//
//   SourceMap sources;
//   Diagnostics diags;
//   auto scene = runtime::load_scene("examples/scenes/unlit.json", sources, diags);
//   if (!scene) { fputs(render_text(diags, sources).c_str(), stderr); return 1; }
#pragma once

#include <cstdint>

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "facet/diagnostics.h"
#include "facet/result.h"
#include "facet/runtime/mesh.h"

namespace facet::runtime {

using Vec3 = std::array<float, 3>;
using Vec4 = std::array<float, 4>;

// Position, Unity Euler angles in degrees (applied Z, then X, then Y) and
// scale; `look_at` (a world point) replaces the rotation when present.
struct Transform {
  Vec3 position{0, 0, 0};
  Vec3 rotation{0, 0, 0};
  Vec3 scale{1, 1, 1};
  std::optional<Vec3> look_at;
  bool operator==(const Transform&) const = default;
};

enum class Projection { perspective, orthographic };

struct SceneCamera {
  Projection projection = Projection::perspective;
  Transform transform;     // looks along its local +Z, as Unity's cameras
  float fov = 60;          // vertical, degrees
  float size = 5;          // orthographic half height
  float near = 0.3f, far = 1000;
  Vec4 clear_color{0.19f, 0.30f, 0.47f, 1};  // sRGB-authored, as in Unity
  bool clear_sky = false;  // "clear": "sky": the ambient's procedural sky behind everything
  float exposure = 1;
  // Unity's Camera.renderingPath: deferred draws the opaque objects whose
  // shader has a LightMode Deferred pass into a G-buffer and lights them
  // there; everything else is drawn forward after it.
  bool deferred = false;
  bool operator==(const SceneCamera&) const = default;
};

// A texture a property names: a built-in ("white", "black", "gray", "bump",
// "red") or a file (path resolved against the scene's folder).
struct SceneTexture {
  std::string name;       // built-in name or resolved path
  bool builtin = false;
  bool srgb = true;       // colour data; false for normal maps, masks, data
  bool alpha_from_gray = false;  // a file without alpha gets alpha = its grey level (cookies)
  // A glTF metallicRoughness texture and the material's (metallic,
  // roughness) factors: the texels become Unity's _MetallicGlossMap,
  // (metallic x B, 0, 0, 1 - roughness x G) (docs/scene-format.md).
  std::optional<std::array<float, 2>> gltf_metallic_roughness;
  std::array<float, 2> scale{1, 1}, offset{0, 0};
  bool operator==(const SceneTexture&) const = default;
};

enum class LightType { directional, point, spot };

// Unity's LightShadows: soft filters 3x3 comparisons (percentage-closer filtering).
enum class ShadowMode { none, hard, soft };

// Unity's LightRenderMode: an important light is always a pixel light, a
// light that is not important never is (it lights per vertex or through SH),
// and auto lights fill the remaining pixel-light slots by importance.
enum class LightRenderMode { automatic, important, not_important };

struct SceneLight {
  LightType type = LightType::directional;
  std::string json_path;    // "lights[1]"
  Transform transform;      // a directional or spot light shines along its +Z
  Vec3 color{1, 1, 1};      // sRGB-authored
  float intensity = 1;
  float range = 10;         // point and spot
  float spot_angle = 30;    // full cone, degrees
  float inner_spot_angle = 21.8f;
  ShadowMode shadows = ShadowMode::none;  // directional and spot lights (point lights: not rendered)
  float shadow_strength = 1;              // 0..1: how dark the shadow is
  float shadow_bias = 1;                  // depth bias, in shadow-map texels (their world size)
  float shadow_normal_bias = 0.4f;        // casters shrunk along their normals, in texels
  // The cookie's alpha masks the light (Unity's _LightTexture0.w): spot
  // lights project it over the cone, directional lights repeat it every
  // cookie_size world units in the light's XY plane. Point lights have none.
  std::optional<SceneTexture> cookie;
  float cookie_size = 10;   // directional, world units (Unity's Light.cookieSize)
  LightRenderMode render_mode = LightRenderMode::automatic;
  bool operator==(const SceneLight&) const = default;
};

// A procedural sky for the ambient light (sRGB-authored colours): radiance
// horizon -> zenith linearly in the direction's y above the horizon, horizon
// -> ground linearly in -y below, times intensity (facet/runtime/sky_sh.h).
// The sky's sun (Unity's procedural skybox's "Sun Source"): a disc in the
// direction a directional light comes from, its colour, `size` degrees
// across, radiance the light's linear colour x intensity.
struct SceneSkySun {
  int light = 0;           // into scene.lights: a directional light
  float size = 1.5f;       // angular diameter, degrees
  float intensity = 20;    // radiance per unit of the light's linear colour x intensity
  bool operator==(const SceneSkySun&) const = default;
};

struct SceneSky {
  Vec3 zenith{0.2f, 0.45f, 0.8f}, horizon{0.75f, 0.8f, 0.85f}, ground{0.3f, 0.27f, 0.22f};
  float intensity = 1;
  std::optional<SceneSkySun> sun;
  bool operator==(const SceneSky&) const = default;
};

// The environment every object reflects (docs/scene-format.md): an
// equirectangular HDR image or a uniform radiance, as a GGX-prefiltered cube
// in unity_SpecCube0 (facet/runtime/environment.h); also the ambient SH
// unless the scene gives `ambient`, and what camera.clear "sky" draws.
struct SceneEnvironment {
  std::string file;           // resolved path of a linear .hdr or .exr image; empty: `color`
  Vec3 color{1, 1, 1};        // linear radiance of a uniform environment
  float intensity = 1;
  float rotation = 0;         // degrees about +Y, as Skybox/Panoramic's _Rotation
  int resolution = 128;       // texels a side of the cube's faces (a power of two)
  bool operator==(const SceneEnvironment&) const = default;
};

// A reflection probe (Unity's ReflectionProbe, rendered once when the scene
// loads): the scene seen from `position` through six 90-degree faces,
// GGX-prefiltered as the environment is; objects whose centre lies in its
// box reflect it (docs/rendering.md, "Reflection probes").
struct SceneReflectionProbe {
  std::string json_path;      // "reflection_probes[0]"
  Vec3 position{0, 0, 0};
  Vec3 size{10, 10, 10};      // the box, centred on position
  bool box_projection = false;
  int importance = 1;
  float blend_distance = 1;   // world units inside the box over which it fades out
  float intensity = 1;
  int resolution = 64;        // texels a side of each face (a power of two)
  bool operator==(const SceneReflectionProbe&) const = default;
};

enum class FogMode { off, linear, exp, exp2 };

struct SceneFog {
  FogMode mode = FogMode::off;
  Vec4 color{0.5f, 0.5f, 0.5f, 1};  // sRGB-authored
  float start = 0, end = 300, density = 0.01f;
  bool operator==(const SceneFog&) const = default;
};

enum class Tonemap { none, reinhard, aces };

// One entry of material.properties, before the shader says what it must be.
struct SceneProperty {
  std::string name;
  std::string json_path;            // "objects[0].material.properties._Color"
  std::vector<float> numbers;       // a number or a list of numbers
  std::optional<SceneTexture> texture;
  bool if_declared = false;         // from a glTF material: skipped when the shader has no such property
  bool operator==(const SceneProperty&) const = default;
};

struct SceneMaterial {
  std::string shader;               // resolved path of the .shader file
  std::string json_path;            // "objects[0].material"
  std::vector<SceneProperty> properties;
  // Values of shader uniforms no property declares (Unity's
  // Material.SetMatrix, or SetFloat of an undeclared name), written to the
  // members of that name: a matrix as 16 floats in column-major order, a
  // vector as up to 4, an array element after element.
  std::map<std::string, std::vector<float>> uniforms;
  std::vector<std::string> keywords;
  std::optional<int> queue;         // render queue override
  // Unity's Material.enableInstancing: INSTANCING_ON for the passes that
  // declare it (multi_compile_instancing), and consecutive draws of the
  // same mesh, pass variant, light and material values drawn as one
  // instanced draw (docs/rendering.md, "GPU instancing").
  bool instancing = false;
  bool operator==(const SceneMaterial&) const = default;
};

struct SceneObject {
  std::string name;
  std::string json_path;            // "objects[0]"
  std::string mesh;                 // built-in name or resolved .obj, .gltf or .glb path
  bool builtin_mesh = true;
  // A glTF mesh with "gltf_materials": only the primitives of this glTF
  // material (-1: those without one); all primitives when absent.
  std::optional<int> gltf_material;
  Transform transform;
  SceneMaterial material;
  // An engine's own geometry, drawn instead of `mesh` (which then only names
  // it in messages): uploaded once per MeshData object, kept while a
  // Renderer keeps its frame. Its indices are checked against its vertices.
  std::shared_ptr<const MeshData> mesh_data;
  bool operator==(const SceneObject&) const = default;
};

// One step of the image-effect chain, as Unity's Graphics.Blit(source,
// destination, material, pass): the previous image is bound as _MainTex.
struct ScenePostEffect {
  std::string json_path;            // "post[0]"
  SceneMaterial material;
  int pass = 0;                     // into the passes of the shader's SubShader
  bool operator==(const ScenePostEffect&) const = default;
};

// A frame of at most this many pixels (4096 x 4096; each side at most
// 16384): its images, on the CPU and in a CPU driver's memory, stay under
// 2 GB. Reflection probes render at most kMaxProbeTexels texels together
// (six faces each), at most 256 a side.
inline constexpr int64_t kMaxFramePixels = int64_t(4096) * 4096;
inline constexpr int64_t kMaxProbeTexels = int64_t(4) * 6 * 256 * 256;
// Keywords one material may enable (Unity allows 64 local and 256 global).
inline constexpr size_t kMaxMaterialKeywords = 1024;

struct Scene {
  std::string path;                 // as given, for messages
  int width = 256, height = 256;
  float time = 0;                   // seconds, for _Time
  SceneCamera camera;
  std::vector<SceneLight> lights;
  std::vector<SceneObject> objects;
  Vec3 ambient{0.2f, 0.2f, 0.2f};   // sRGB-authored flat ambient
  std::optional<SceneSky> sky;      // replaces the flat ambient when present
  bool ambient_given = false;       // `ambient` was written (else an environment supplies it)
  std::optional<SceneEnvironment> environment;
  std::vector<SceneReflectionProbe> reflection_probes;
  SceneFog fog;
  Tonemap tonemap = Tonemap::none;
  int pixel_light_count = 4;        // Unity's default pixel light limit
  int shadow_resolution = 1024;     // texels per side of each shadow map
  float shadow_distance = 50;       // directional shadows cover what lies this close to the camera
  int shadow_cascades = 1;          // 1, 2 or 4: a directional light's map split along the view (Unity's splits)
  std::vector<ScenePostEffect> post;  // image effects, in order, before tone mapping
  bool operator==(const Scene&) const = default;
};

// Parses `text`; `path` names the file in messages and anchors relative
// paths. The text is added to `sources` and each error is located in it: a
// syntax error where it is (scene_json_syntax), a value the reader rejects
// at that value, with its JSON path in the message
// ("objects[2].material.properties._Color: expected 4 numbers",
// scene_invalid).
Result<Scene> parse_scene(const std::string& text, const std::string& path, SourceMap& sources, Diagnostics& diags);
// Reads the file first (scene_unreadable: missing, unreadable, over 64 MiB).
Result<Scene> load_scene(const std::string& path, SourceMap& sources, Diagnostics& diags);

}  // namespace facet::runtime
