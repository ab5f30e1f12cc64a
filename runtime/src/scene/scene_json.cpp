// The JSON reader of docs/scene-format.md. Every check names the JSON path
// of the value it rejects; unknown keys are errors so that a misspelt key
// does not silently keep its default. Hostile input gets an error too: a
// number no double holds (1e400) is located like a syntax error, numbers
// must fit a float, nesting is limited, and no exception of nlohmann or
// std::filesystem leaves parse_scene.
#include <fmt/format.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <new>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>

#include "facet/runtime/gltf.h"
#include "facet/runtime/mesh.h"
#include "facet/runtime/scene.h"
#include "scene/gltf_material.h"
#include "scene/json_locate.h"

namespace facet::runtime {
namespace {

using nlohmann::json;

// Thrown inside this file only, caught by parse_scene: the reader's checks
// nest deeply and an exception keeps each of them one line.
struct Bad {
  std::string path, what;
};

std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }
std::string index(const std::string& path, size_t i) { return fmt::format("{}[{}]", path, i); }

const json& member(const json& object, const char* key) { return object.at(key); }

void check_keys(const json& j, const std::string& path, std::initializer_list<const char*> allowed) {
  if (!j.is_object()) throw Bad{path, "expected an object"};
  std::set<std::string> keys(allowed.begin(), allowed.end());
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (!keys.count(it.key())) {
      std::string list;
      for (const char* k : allowed) list += std::string(list.empty() ? "" : ", ") + k;
      throw Bad{join(path, it.key()), fmt::format("unknown key (expected one of: {})", list)};
    }
  }
}

// Every number of a scene becomes a float: one past float's range would be
// infinite, and an infinite size or angle reaches the matrices as NaN.
float number(const json& j, const std::string& path) {
  if (!j.is_number()) throw Bad{path, "expected a number"};
  double v = j.get<double>();
  if (!std::isfinite(v) || std::abs(v) > double(FLT_MAX)) {
    throw Bad{path, fmt::format("the number {} is out of range (a scene's numbers are floats, at most {:g})", j.dump(),
                                double(FLT_MAX))};
  }
  return float(v);
}

float positive(const json& j, const std::string& path) {
  float v = number(j, path);
  if (!(v > 0)) throw Bad{path, "expected a number above 0"};
  return v;
}

std::vector<float> numbers(const json& j, const std::string& path, size_t min, size_t max) {
  std::string want = min == max ? fmt::format("{} numbers", min) : fmt::format("{} to {} numbers", min, max);
  if (!j.is_array() || j.size() < min || j.size() > max) throw Bad{path, "expected " + want};
  std::vector<float> out;
  for (size_t i = 0; i < j.size(); ++i) {
    if (!j[i].is_number()) throw Bad{path, "expected " + want};
    out.push_back(number(j[i], index(path, i)));
  }
  return out;
}

Vec3 vec3(const json& j, const std::string& path) {
  std::vector<float> v = numbers(j, path, 3, 3);
  return {v[0], v[1], v[2]};
}

// Colours: 3 numbers (alpha 1) or 4.
Vec4 color(const json& j, const std::string& path) {
  std::vector<float> v = numbers(j, path, 3, 4);
  return {v[0], v[1], v[2], v.size() == 4 ? v[3] : 1.0f};
}

std::string text(const json& j, const std::string& path) {
  if (!j.is_string()) throw Bad{path, "expected a string"};
  return j.get<std::string>();
}

template <typename E>
E word(const json& j, const std::string& path, std::initializer_list<std::pair<const char*, E>> words) {
  std::string w = text(j, path);
  std::string list;
  for (auto& [name, value] : words) {
    if (w == name) return value;
    list += std::string(list.empty() ? "" : ", ") + name;
  }
  throw Bad{path, fmt::format("unknown value '{}' (expected one of: {})", w, list)};
}

// nlohmann keeps non-negative integers unsigned (up to 2^64 - 1), so both
// kinds are compared before narrowing: 2^64 - 1 must not wrap to -1.
int integer(const json& j, const std::string& path, int min, int max) {
  bool in_range = false;
  if (j.is_number_unsigned()) {
    uint64_t v = j.get<uint64_t>();
    in_range = v <= uint64_t(max) && int64_t(v) >= min;
  } else if (j.is_number_integer()) {
    int64_t v = j.get<int64_t>();
    in_range = v >= min && v <= max;
  }
  if (!in_range) throw Bad{path, fmt::format("expected an integer from {} to {}", min, max)};
  return int(j.get<int64_t>());
}

// A file test that reports instead of throwing: a name too long for the
// file system (ENAMETOOLONG) makes the throwing overload abort the reader.
bool is_file(const std::string& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

struct Reader {
  std::filesystem::path dir;

  std::string resolve(const std::string& relative) const {
    std::filesystem::path p(relative);
    return (p.is_absolute() ? p : dir / p).lexically_normal().string();
  }

  Transform transform(const json& j, const std::string& path) const {
    Transform t;
    if (j.contains("position")) t.position = vec3(member(j, "position"), join(path, "position"));
    if (j.contains("rotation")) t.rotation = vec3(member(j, "rotation"), join(path, "rotation"));
    if (j.contains("look_at")) t.look_at = vec3(member(j, "look_at"), join(path, "look_at"));
    if (j.contains("scale")) {
      const json& s = member(j, "scale");
      if (s.is_number()) {
        float v = number(s, join(path, "scale"));
        t.scale = {v, v, v};
      } else {
        t.scale = vec3(s, join(path, "scale"));
      }
    }
    return t;
  }

  SceneCamera camera(const json& j, const std::string& path) const {
    check_keys(j, path, {"type", "position", "rotation", "look_at", "fov", "size", "near", "far", "clear_color",
                         "clear", "exposure", "rendering_path"});
    SceneCamera c;
    c.transform = transform(j, path);
    if (j.contains("type")) {
      c.projection = word<Projection>(member(j, "type"), join(path, "type"),
                                      {{"perspective", Projection::perspective}, {"orthographic", Projection::orthographic}});
    }
    if (j.contains("fov")) c.fov = positive(member(j, "fov"), join(path, "fov"));
    if (c.fov >= 180) throw Bad{join(path, "fov"), "expected an angle below 180 degrees"};
    if (j.contains("size")) c.size = positive(member(j, "size"), join(path, "size"));
    if (j.contains("near")) c.near = positive(member(j, "near"), join(path, "near"));
    if (j.contains("far")) c.far = positive(member(j, "far"), join(path, "far"));
    if (c.far <= c.near) throw Bad{join(path, "far"), "expected far > near"};
    if (j.contains("clear_color")) c.clear_color = color(member(j, "clear_color"), join(path, "clear_color"));
    if (j.contains("clear")) {
      c.clear_sky = word<bool>(member(j, "clear"), join(path, "clear"), {{"color", false}, {"sky", true}});
    }
    if (j.contains("exposure")) c.exposure = positive(member(j, "exposure"), join(path, "exposure"));
    if (j.contains("rendering_path")) {
      c.deferred = word<bool>(member(j, "rendering_path"), join(path, "rendering_path"),
                              {{"forward", false}, {"deferred", true}});
    }
    return c;
  }

  static void shadow_settings(const json& j, const std::string& path, SceneLight& l) {
    if (j.contains("shadows")) {
      l.shadows = word<ShadowMode>(member(j, "shadows"), join(path, "shadows"),
                                   {{"none", ShadowMode::none}, {"hard", ShadowMode::hard}, {"soft", ShadowMode::soft}});
    }
    auto fraction = [&](const char* key, float& out, float max) {
      if (!j.contains(key)) return;
      out = number(member(j, key), join(path, key));
      if (out < 0 || out > max) throw Bad{join(path, key), fmt::format("expected a number from 0 to {}", max)};
    };
    fraction("shadow_strength", l.shadow_strength, 1);
    fraction("shadow_bias", l.shadow_bias, 10);
    fraction("shadow_normal_bias", l.shadow_normal_bias, 10);
  }

  SceneLight light(const json& j, const std::string& path) const {
    check_keys(j, path, {"type", "position", "rotation", "look_at", "color", "intensity", "range", "spot_angle",
                         "inner_spot_angle", "shadows", "shadow_strength", "shadow_bias", "shadow_normal_bias",
                         "cookie", "cookie_size", "render_mode"});
    SceneLight l;
    l.json_path = path;
    if (!j.contains("type")) throw Bad{path, "missing key 'type' (directional, point or spot)"};
    l.type = word<LightType>(member(j, "type"), join(path, "type"),
                             {{"directional", LightType::directional}, {"point", LightType::point}, {"spot", LightType::spot}});
    l.transform = transform(j, path);
    if (l.type == LightType::directional && !j.contains("rotation") && !j.contains("look_at")) {
      l.transform.rotation = {50, -30, 0};  // Unity's default sun
    }
    if (j.contains("color")) {
      Vec4 c = color(member(j, "color"), join(path, "color"));
      l.color = {c[0], c[1], c[2]};
    }
    if (j.contains("intensity")) {
      l.intensity = number(member(j, "intensity"), join(path, "intensity"));
      if (l.intensity < 0) throw Bad{join(path, "intensity"), "expected a number >= 0"};
    }
    if (j.contains("range")) l.range = positive(member(j, "range"), join(path, "range"));
    if (j.contains("spot_angle")) l.spot_angle = positive(member(j, "spot_angle"), join(path, "spot_angle"));
    if (l.spot_angle >= 180) throw Bad{join(path, "spot_angle"), "expected an angle below 180 degrees"};
    l.inner_spot_angle = std::min(l.inner_spot_angle, l.spot_angle);
    if (j.contains("inner_spot_angle")) {
      l.inner_spot_angle = number(member(j, "inner_spot_angle"), join(path, "inner_spot_angle"));
      if (l.inner_spot_angle < 0 || l.inner_spot_angle > l.spot_angle) {
        throw Bad{join(path, "inner_spot_angle"), "expected an angle from 0 to spot_angle"};
      }
    }
    if (j.contains("render_mode")) {
      l.render_mode = word<LightRenderMode>(member(j, "render_mode"), join(path, "render_mode"),
                                            {{"auto", LightRenderMode::automatic},
                                             {"important", LightRenderMode::important},
                                             {"not_important", LightRenderMode::not_important}});
    }
    shadow_settings(j, path, l);
    cookie(j, path, l);
    return l;
  }

  // A cookie is a texture name (a file or a built-in); its alpha is the mask,
  // so a file without alpha gives its grey level, as Unity's cookie import.
  void cookie(const json& j, const std::string& path, SceneLight& l) const {
    if (j.contains("cookie")) {
      std::string cpath = join(path, "cookie");
      if (l.type == LightType::point) {
        throw Bad{cpath, "point lights take no cookie (cube cookies are not supported; use a spot or directional light)"};
      }
      if (!member(j, "cookie").is_string()) throw Bad{cpath, "expected a texture file name or a built-in texture name"};
      l.cookie = texture(member(j, "cookie"), cpath);
      l.cookie->srgb = false;
      l.cookie->alpha_from_gray = true;
    }
    if (j.contains("cookie_size")) {
      if (l.type != LightType::directional) {
        throw Bad{join(path, "cookie_size"), "only a directional light's cookie has a size (a spot's fills its cone)"};
      }
      l.cookie_size = positive(member(j, "cookie_size"), join(path, "cookie_size"));
    }
  }

  SceneTexture texture(const json& j, const std::string& path) const {
    SceneTexture t;
    std::string name;
    if (j.is_string()) {
      name = j.get<std::string>();
    } else {
      check_keys(j, path, {"texture", "srgb", "scale", "offset"});
      if (!j.contains("texture")) throw Bad{path, "missing key 'texture'"};
      name = text(member(j, "texture"), join(path, "texture"));
      if (j.contains("srgb")) {
        if (!member(j, "srgb").is_boolean()) throw Bad{join(path, "srgb"), "expected true or false"};
        t.srgb = member(j, "srgb").get<bool>();
      }
      if (j.contains("scale")) {
        std::vector<float> v = numbers(member(j, "scale"), join(path, "scale"), 2, 2);
        t.scale = {v[0], v[1]};
      }
      if (j.contains("offset")) {
        std::vector<float> v = numbers(member(j, "offset"), join(path, "offset"), 2, 2);
        t.offset = {v[0], v[1]};
      }
    }
    static const std::set<std::string> builtins = {"white", "black", "gray", "grey", "bump", "red"};
    t.builtin = builtins.count(name) != 0;
    t.name = t.builtin ? name : resolve(name);
    if (!t.builtin && !is_file(t.name)) {
      throw Bad{j.is_string() ? path : join(path, "texture"), fmt::format("texture file '{}' not found", t.name)};
    }
    return t;
  }

  SceneProperty property(const std::string& name, const json& j, const std::string& path) const {
    SceneProperty p;
    p.name = name;
    p.json_path = path;
    if (j.is_number()) {
      p.numbers = {number(j, path)};
    } else if (j.is_boolean()) {
      p.numbers = {j.get<bool>() ? 1.0f : 0.0f};
    } else if (j.is_array()) {
      p.numbers = numbers(j, path, 1, 4);
    } else if (j.is_string() || j.is_object()) {
      p.texture = texture(j, path);
    } else {
      throw Bad{path, "expected a number, a list of numbers, or a texture"};
    }
    return p;
  }

  // `post_pass`: the object is a post effect's, which may also hold "pass"
  // (read by post_effect).
  SceneMaterial material(const json& j, const std::string& path, bool post_pass = false) const {
    if (post_pass) {
      check_keys(j, path, {"shader", "properties", "keywords", "pass"});
    } else {
      check_keys(j, path, {"shader", "properties", "keywords", "queue", "instancing"});
    }
    SceneMaterial m;
    m.json_path = path;
    if (!j.contains("shader")) throw Bad{path, "missing key 'shader' (a .shader file or a .facetpkg package)"};
    m.shader = resolve(text(member(j, "shader"), join(path, "shader")));
    if (!is_file(m.shader)) {
      throw Bad{join(path, "shader"), fmt::format("shader file '{}' not found", m.shader)};
    }
    if (j.contains("properties")) {
      const json& props = member(j, "properties");
      std::string ppath = join(path, "properties");
      if (!props.is_object()) throw Bad{ppath, "expected an object of property values"};
      for (auto it = props.begin(); it != props.end(); ++it) {
        m.properties.push_back(property(it.key(), it.value(), join(ppath, it.key())));
      }
    }
    if (j.contains("keywords")) {
      const json& k = member(j, "keywords");
      if (!k.is_array()) throw Bad{join(path, "keywords"), "expected a list of keyword strings"};
      if (k.size() > kMaxMaterialKeywords) {
        throw Bad{join(path, "keywords"), fmt::format("more than {} keywords", kMaxMaterialKeywords)};
      }
      for (size_t i = 0; i < k.size(); ++i) m.keywords.push_back(text(k[i], index(join(path, "keywords"), i)));
    }
    if (j.contains("queue")) m.queue = integer(member(j, "queue"), join(path, "queue"), 0, 5000);
    if (j.contains("instancing")) {
      if (!member(j, "instancing").is_boolean()) throw Bad{join(path, "instancing"), "expected true or false"};
      m.instancing = member(j, "instancing").get<bool>();
    }
    return m;
  }

  // One object of the file, or with "gltf_materials" one per glTF material
  // its mesh uses, each with that material mapped onto its own.
  void object(const json& j, const std::string& path, std::vector<SceneObject>& out) const {
    check_keys(j, path, {"name", "mesh", "position", "rotation", "look_at", "scale", "material", "gltf_materials"});
    SceneObject o;
    o.json_path = path;
    if (j.contains("name")) o.name = text(member(j, "name"), join(path, "name"));
    if (!j.contains("mesh")) throw Bad{path, "missing key 'mesh'"};
    std::string mesh = text(member(j, "mesh"), join(path, "mesh"));
    const std::vector<std::string>& names = builtin_mesh_names();
    o.builtin_mesh = std::find(names.begin(), names.end(), mesh) != names.end();
    if (o.builtin_mesh) {
      o.mesh = mesh;
    } else {
      o.mesh = resolve(mesh);
      if (!is_file(o.mesh)) {
        throw Bad{join(path, "mesh"), fmt::format("not a built-in mesh (cube, plane, quad, sphere, torus) and no file '{}'",
                                                  o.mesh)};
      }
    }
    o.transform = transform(j, path);
    if (!j.contains("material")) throw Bad{path, "missing key 'material'"};
    o.material = material(member(j, "material"), join(path, "material"));
    bool gltf_materials = false;
    if (j.contains("gltf_materials")) {
      const json& g = member(j, "gltf_materials");
      if (!g.is_boolean()) throw Bad{join(path, "gltf_materials"), "expected true or false"};
      gltf_materials = g.get<bool>();
      if (gltf_materials && (o.builtin_mesh || !is_gltf_path(o.mesh))) {
        throw Bad{join(path, "gltf_materials"), "needs a glTF mesh (a .gltf or .glb file)"};
      }
    }
    if (!gltf_materials) {
      out.push_back(std::move(o));
      return;
    }
    Diagnostics mesh_diags;
    std::optional<GltfModel> model = load_gltf(o.mesh, mesh_diags, {.materials = true});
    if (!model) throw Bad{join(path, "mesh"), mesh_diags.all().empty() ? "does not load" : mesh_diags.all().front().message};
    for (const GltfPart& part : model->parts) {
      SceneObject each = o;
      each.gltf_material = part.material;
      // Primitives without a material get glTF's default one (GltfMaterial's defaults).
      GltfMaterial gltf = part.material >= 0 ? model->materials[size_t(part.material)] : GltfMaterial{};
      Result<SceneMaterial, std::string> m = with_gltf_material(o.material, gltf, part.material);
      if (!m) throw Bad{join(path, "mesh"), o.mesh + ": " + m.error()};
      each.material = std::move(*m);
      out.push_back(std::move(each));
    }
  }

  SceneFog fog(const json& j, const std::string& path) const {
    check_keys(j, path, {"mode", "color", "start", "end", "density"});
    SceneFog f;
    f.mode = FogMode::linear;
    if (j.contains("mode")) {
      f.mode = word<FogMode>(member(j, "mode"), join(path, "mode"),
                             {{"off", FogMode::off}, {"linear", FogMode::linear}, {"exp", FogMode::exp}, {"exp2", FogMode::exp2}});
    }
    if (j.contains("color")) f.color = color(member(j, "color"), join(path, "color"));
    if (j.contains("start")) f.start = number(member(j, "start"), join(path, "start"));
    if (j.contains("end")) f.end = number(member(j, "end"), join(path, "end"));
    if (f.end <= f.start) throw Bad{join(path, "end"), "expected end > start"};
    if (j.contains("density")) f.density = number(member(j, "density"), join(path, "density"));
    return f;
  }

  // A flat colour, or {"sky": {...}}: a procedural sky projected onto SH.
  void ambient(const json& j, Scene& s) const {
    if (j.is_array()) {
      Vec4 c = color(j, "ambient");
      s.ambient = {c[0], c[1], c[2]};
      return;
    }
    if (!j.is_object()) throw Bad{"ambient", "expected a colour (3 or 4 numbers) or {\"sky\": {...}}"};
    check_keys(j, "ambient", {"sky"});
    if (!j.contains("sky")) throw Bad{"ambient", "missing key 'sky'"};
    const json& k = member(j, "sky");
    const std::string path = "ambient.sky";
    check_keys(k, path, {"zenith", "horizon", "ground", "intensity", "sun"});
    SceneSky sky;
    for (auto [key, slot] : {std::pair{"zenith", &sky.zenith}, std::pair{"horizon", &sky.horizon}, std::pair{"ground", &sky.ground}}) {
      if (!k.contains(key)) continue;
      Vec4 c = color(member(k, key), join(path, key));
      *slot = {c[0], c[1], c[2]};
    }
    if (k.contains("intensity")) {
      sky.intensity = number(member(k, "intensity"), join(path, "intensity"));
      if (sky.intensity < 0) throw Bad{join(path, "intensity"), "expected a number >= 0"};
    }
    if (k.contains("sun")) sky.sun = sun(member(k, "sun"), join(path, "sun"), s);
    s.sky = sky;
  }

  SceneSkySun sun(const json& j, const std::string& path, const Scene& s) const {
    if (!j.is_object()) throw Bad{path, "expected {\"light\": INDEX, \"size\": DEGREES, \"intensity\": N}"};
    check_keys(j, path, {"light", "size", "intensity"});
    SceneSkySun sun;
    if (!j.contains("light")) throw Bad{path, "missing key 'light' (the directional light the sun shines as)"};
    sun.light = integer(member(j, "light"), join(path, "light"), 0, 1 << 20);
    if (size_t(sun.light) >= s.lights.size() || s.lights[size_t(sun.light)].type != LightType::directional) {
      throw Bad{join(path, "light"), fmt::format("expected the index of a directional light (lights[0..{}])",
                                                  s.lights.empty() ? 0 : s.lights.size() - 1)};
    }
    if (j.contains("size")) {
      sun.size = number(member(j, "size"), join(path, "size"));
      if (!(sun.size > 0 && sun.size <= 20)) throw Bad{join(path, "size"), "expected degrees in (0, 20]"};
    }
    if (j.contains("intensity")) {
      sun.intensity = number(member(j, "intensity"), join(path, "intensity"));
      if (!(sun.intensity >= 0)) throw Bad{join(path, "intensity"), "expected a number >= 0"};
    }
    return sun;
  }

  SceneEnvironment environment(const json& j) const {
    const std::string path = "environment";
    if (!j.is_object()) throw Bad{path, "expected {\"file\": \"image.hdr\"} or {\"color\": [r, g, b]}"};
    check_keys(j, path, {"file", "color", "intensity", "rotation", "resolution"});
    if (j.contains("file") == j.contains("color")) throw Bad{path, "expected exactly one of 'file' and 'color'"};
    SceneEnvironment e;
    if (j.contains("file")) e.file = resolve(text(member(j, "file"), join(path, "file")));
    if (j.contains("color")) {
      // Linear radiance, not an sRGB-authored colour: an HDR environment's unit.
      const json& c = member(j, "color");
      if (!c.is_array() || c.size() != 3) throw Bad{join(path, "color"), "expected 3 numbers (linear radiance)"};
      for (size_t i = 0; i < 3; ++i) {
        e.color[i] = number(c[i], index(join(path, "color"), i));
        if (!(e.color[i] >= 0)) throw Bad{index(join(path, "color"), i), "expected a number >= 0"};
      }
    }
    if (j.contains("intensity")) {
      e.intensity = number(member(j, "intensity"), join(path, "intensity"));
      if (!(e.intensity >= 0)) throw Bad{join(path, "intensity"), "expected a number >= 0"};
    }
    if (j.contains("rotation")) e.rotation = number(member(j, "rotation"), join(path, "rotation"));
    if (j.contains("resolution")) {
      e.resolution = integer(member(j, "resolution"), join(path, "resolution"), 8, 512);
      if ((e.resolution & (e.resolution - 1)) != 0) throw Bad{join(path, "resolution"), "expected a power of two"};
    }
    return e;
  }

  SceneReflectionProbe reflection_probe(const json& j, const std::string& path) const {
    if (!j.is_object()) throw Bad{path, "expected a reflection probe object"};
    check_keys(j, path, {"position", "size", "box_projection", "importance", "blend_distance", "intensity", "resolution"});
    SceneReflectionProbe p;
    p.json_path = path;
    auto vec3 = [&](const char* key, Vec3& out, bool positive) {
      const json& v = member(j, key);
      const std::string at = join(path, key);
      if (!v.is_array() || v.size() != 3) throw Bad{at, "expected 3 numbers"};
      for (size_t i = 0; i < 3; ++i) {
        out[i] = number(v[i], index(at, i));
        if (positive && !(out[i] > 0)) throw Bad{index(at, i), "expected a number > 0"};
      }
    };
    if (j.contains("position")) vec3("position", p.position, false);
    if (j.contains("size")) vec3("size", p.size, true);
    if (j.contains("box_projection")) {
      const json& b = member(j, "box_projection");
      if (!b.is_boolean()) throw Bad{join(path, "box_projection"), "expected true or false"};
      p.box_projection = b.get<bool>();
    }
    if (j.contains("importance")) p.importance = integer(member(j, "importance"), join(path, "importance"), 0, 1000000);
    if (j.contains("blend_distance")) {
      p.blend_distance = number(member(j, "blend_distance"), join(path, "blend_distance"));
      if (!(p.blend_distance >= 0)) throw Bad{join(path, "blend_distance"), "expected a number >= 0"};
    }
    if (j.contains("intensity")) {
      p.intensity = number(member(j, "intensity"), join(path, "intensity"));
      if (!(p.intensity >= 0)) throw Bad{join(path, "intensity"), "expected a number >= 0"};
    }
    if (j.contains("resolution")) {
      p.resolution = integer(member(j, "resolution"), join(path, "resolution"), 16, 256);
      if ((p.resolution & (p.resolution - 1)) != 0) throw Bad{join(path, "resolution"), "expected a power of two"};
    }
    return p;
  }

  // A material plus the pass to blit with.
  ScenePostEffect post_effect(const json& j, const std::string& path) const {
    check_keys(j, path, {"shader", "properties", "keywords", "pass"});
    ScenePostEffect e;
    e.json_path = path;
    if (j.contains("pass")) e.pass = integer(member(j, "pass"), join(path, "pass"), 0, 63);
    // No copy of `j` without "pass": copying a json value recurses, and
    // deeply nested properties would overflow the stack.
    e.material = material(j, path, true);
    return e;
  }

  Scene scene(const json& j) const {
    check_keys(j, "", {"width", "height", "time", "camera", "lights", "objects", "ambient", "fog", "tonemap",
                       "pixel_light_count", "post", "shadow_resolution", "shadow_distance", "shadow_cascades",
                       "environment", "reflection_probes"});
    Scene s;
    if (j.contains("width")) s.width = integer(member(j, "width"), "width", 1, 16384);
    if (j.contains("height")) s.height = integer(member(j, "height"), "height", 1, 16384);
    if (int64_t(s.width) * s.height > kMaxFramePixels) {
      throw Bad{
          j.contains("height") ? "height" : "width",
          fmt::format("a frame of {} x {} is more than {} pixels (4096 x 4096)", s.width, s.height, kMaxFramePixels)};
    }
    if (j.contains("time")) s.time = number(member(j, "time"), "time");
    if (!j.contains("camera")) throw Bad{"camera", "missing (every scene needs a camera)"};
    s.camera = camera(member(j, "camera"), "camera");
    if (j.contains("lights")) {
      const json& lights = member(j, "lights");
      if (!lights.is_array()) throw Bad{"lights", "expected a list of lights"};
      for (size_t i = 0; i < lights.size(); ++i) s.lights.push_back(light(lights[i], index("lights", i)));
    }
    if (!j.contains("objects")) throw Bad{"objects", "missing (a list of objects)"};
    const json& objects = member(j, "objects");
    if (!objects.is_array()) throw Bad{"objects", "expected a list of objects"};
    for (size_t i = 0; i < objects.size(); ++i) object(objects[i], index("objects", i), s.objects);
    if (j.contains("ambient")) ambient(member(j, "ambient"), s);
    s.ambient_given = j.contains("ambient");
    if (j.contains("environment")) s.environment = environment(member(j, "environment"));
    if (j.contains("reflection_probes")) {
      const json& probes = member(j, "reflection_probes");
      if (!probes.is_array()) throw Bad{"reflection_probes", "expected a list of reflection probes"};
      if (probes.size() > 16) throw Bad{"reflection_probes", "expected at most 16 probes (each renders the scene six times)"};
      int64_t texels = 0;
      for (size_t i = 0; i < probes.size(); ++i) {
        s.reflection_probes.push_back(reflection_probe(probes[i], index("reflection_probes", i)));
        texels += int64_t(6) * s.reflection_probes.back().resolution * s.reflection_probes.back().resolution;
        if (texels > kMaxProbeTexels) {
          throw Bad{index("reflection_probes", i),
                    fmt::format("the probes render more than {} texels together (four probes of 256, six faces "
                                "each): each face renders the scene",
                                kMaxProbeTexels)};
        }
      }
    }
    if (s.camera.clear_sky && !s.sky && !s.environment) {
      throw Bad{"camera.clear",
                "\"sky\" needs something to draw: an environment, or ambient as a procedural sky {\"sky\": {...}}"};
    }
    if (j.contains("fog")) s.fog = fog(member(j, "fog"), "fog");
    if (j.contains("tonemap")) {
      s.tonemap = word<Tonemap>(member(j, "tonemap"), "tonemap",
                                {{"none", Tonemap::none}, {"reinhard", Tonemap::reinhard}, {"aces", Tonemap::aces}});
    }
    if (j.contains("pixel_light_count")) s.pixel_light_count = integer(member(j, "pixel_light_count"), "pixel_light_count", 0, 64);
    if (j.contains("shadow_resolution")) {
      s.shadow_resolution = integer(member(j, "shadow_resolution"), "shadow_resolution", 16, 8192);
    }
    if (j.contains("shadow_distance")) s.shadow_distance = positive(member(j, "shadow_distance"), "shadow_distance");
    if (j.contains("shadow_cascades")) {
      s.shadow_cascades = integer(member(j, "shadow_cascades"), "shadow_cascades", 1, 4);
      if (s.shadow_cascades == 3) throw Bad{"shadow_cascades", "expected 1, 2 or 4 (Unity's cascade counts)"};
    }
    if (j.contains("post")) {
      const json& post = member(j, "post");
      if (!post.is_array()) throw Bad{"post", "expected a list of image effects"};
      for (size_t i = 0; i < post.size(); ++i) s.post.push_back(post_effect(post[i], index("post", i)));
    }
    return s;
  }
};

// Deeper than any scene needs (about 6 levels), and shallow enough that no
// recursive walk of a json value can overflow the stack.
constexpr size_t kMaxJsonDepth = 64;

// The byte offset of the first '[' or '{' that opens level kMaxJsonDepth + 1,
// skipping string contents.
std::optional<size_t> too_deep_at(const std::string& text) {
  size_t depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) return i;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return std::nullopt;
}

// nlohmann's DOM builder, keeping where a failure happened: its exceptions
// carry a byte offset only for syntax errors (parse_error), not for a
// number that overflows a double (out_of_range 406).
class LocatingDomBuilder {
 public:
  using Dom = nlohmann::detail::json_sax_dom_parser<json>;
  explicit LocatingDomBuilder(json& root) : dom_(root, false) {}

  bool null() { return dom_.null(); }
  bool boolean(bool v) { return dom_.boolean(v); }
  bool number_integer(json::number_integer_t v) { return dom_.number_integer(v); }
  bool number_unsigned(json::number_unsigned_t v) { return dom_.number_unsigned(v); }
  bool number_float(json::number_float_t v, const json::string_t& s) { return dom_.number_float(v, s); }
  bool string(json::string_t& v) { return dom_.string(v); }
  bool binary(json::binary_t& v) { return dom_.binary(v); }
  bool start_object(size_t n) { return dom_.start_object(n); }
  bool key(json::string_t& v) { return dom_.key(v); }
  bool end_object() { return dom_.end_object(); }
  bool start_array(size_t n) { return dom_.start_array(n); }
  bool end_array() { return dom_.end_array(); }

  // `position` is one past the last byte read; a syntax error is located at
  // the byte before it (as nlohmann's own messages do), any other failure
  // at the start of the token it was reading.
  bool parse_error(size_t position, const std::string& last_token, const nlohmann::detail::exception& e) {
    bool syntax = dynamic_cast<const json::parse_error*>(&e) != nullptr;
    byte_ = syntax ? (position ? position - 1 : 0) : (position >= last_token.size() ? position - last_token.size() : 0);
    std::string what = e.what();
    if (size_t colon = what.rfind(": "); syntax && colon != std::string::npos) {
      what = what.substr(colon + 2);
    } else if (size_t bracket = what.find("] "); bracket != std::string::npos) {
      what = what.substr(bracket + 2);  // drop "[json.exception.out_of_range.406] "
    }
    message_ = what;
    return false;
  }

  size_t byte() const { return byte_; }
  const std::string& message() const { return message_; }

 private:
  Dom dom_;
  size_t byte_ = 0;
  std::string message_ = "cannot parse the JSON";
};

Result<json> parse_json(const std::string& text, FileId file, Diagnostics& diags) {
  auto at = [&](size_t byte) { return SourceSpan{file, uint32_t(byte), uint32_t(byte)}; };
  if (std::optional<size_t> deep = too_deep_at(text)) {
    diags.add(DiagId::scene_json_syntax, at(*deep),
              fmt::format("invalid JSON: nested deeper than {} levels", kMaxJsonDepth));
    return failure();
  }
  json j;
  LocatingDomBuilder builder(j);
  if (!json::sax_parse(text, &builder)) {
    diags.add(DiagId::scene_json_syntax, at(builder.byte()), "invalid JSON: " + builder.message());
    return failure();
  }
  return j;
}

}  // namespace

// The one boundary where exceptions stop: Bad from the reader's checks, and
// whatever nlohmann, std::filesystem or an allocation might still throw.
Result<Scene> parse_scene(const std::string& text, const std::string& path, SourceMap& sources, Diagnostics& diags) {
  const FileId file = sources.add_file(path, text);
  try {
    Result<json> j = parse_json(text, file, diags);
    if (!j) return failure();
    Reader reader{std::filesystem::path(path).parent_path()};
    Scene scene = reader.scene(*j);
    scene.path = path;
    return scene;
  } catch (const Bad& bad) {
    // Where the reader's path cannot be found again (a key holding '.' or
    // '['), the message names the file instead of pointing at line 1.
    SourceSpan span;
    std::string where = path + ": ";
    if (std::optional<JsonExtent> value = locate_json_value(text, bad.path)) {
      span = {file, uint32_t(value->begin), uint32_t(value->end)};
      where.clear();
    }
    diags.add(DiagId::scene_invalid, span, where + (bad.path.empty() ? bad.what : bad.path + ": " + bad.what));
  } catch (const std::bad_alloc&) {
    diags.add(DiagId::scene_unreadable, SourceSpan{file, 0, 0}, "not enough memory to read the scene");
  } catch (const std::exception& e) {
    diags.add(DiagId::scene_invalid, SourceSpan{file, 0, 0}, e.what());
  }
  return failure();
}

Result<Scene> load_scene(const std::string& path, SourceMap& sources, Diagnostics& diags) {
  auto unreadable = [&](std::string why) {
    diags.add(DiagId::scene_unreadable, SourceSpan{}, fmt::format("{}: {}", path, why));
    return failure();
  };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return unreadable("cannot open the scene file (no such file)");
  constexpr uintmax_t kMaxSceneBytes = uintmax_t(64) << 20;  // a scene is a few KiB; its DOM takes ~10x the text
  if (uintmax_t size = std::filesystem::file_size(path, ec); !ec && size > kMaxSceneBytes) {
    return unreadable(
        fmt::format("the scene file has {} bytes, more than the {} MiB a scene may have", size, kMaxSceneBytes >> 20));
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (!in && !in.eof()) return unreadable("cannot read the scene file");
  return parse_scene(buffer.str(), path, sources, diags);
}

}  // namespace facet::runtime
