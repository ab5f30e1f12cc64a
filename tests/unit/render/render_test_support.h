// Scenes written to a temporary folder for the renderer's tests, and the
// shared lavapipe context (validation on, zero messages after each test).
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "facet/commands.h"
#include "facet/runtime/renderer.h"
#include "facet/runtime/scene.h"
#include "facet/runtime/shader_compiler.h"
#include "unit/runtime/context_fixture.h"

namespace facet::runtime::test_support {

// A load's or a render's errors printed as facet prints them
// (render_text: "scene.json:3:7: error: ..."): the tests assert on what a
// user reads. The diagnostics themselves are in `diags`.
struct Printed {
  std::string message;
  Diagnostics diags;
};

// The messages alone, one a line.
inline std::string message_of(const Diagnostics& diags) {
  std::string text;
  for (const Diagnostic& d : diags.all()) text += (text.empty() ? "" : "\n") + d.message;
  return text;
}

// Whether `printed` (render_text's output) has an error located in a file
// whose path ends with `file` ("<...>scene.json:3:7: error: ..."), its
// message starting with `message`.
inline bool has_error_at(const std::string& printed, const std::string& file, const std::string& message) {
  std::istringstream lines(printed);
  for (std::string line; std::getline(lines, line);) {
    size_t at = line.find(file + ":");
    if (at == std::string::npos) continue;
    size_t i = at + file.size() + 1;
    auto digits = [&] {
      size_t start = i;
      while (i < line.size() && std::isdigit(static_cast<unsigned char>(line[i]))) ++i;
      return i > start;
    };
    if (!digits() || i >= line.size() || line[i++] != ':' || !digits()) continue;
    const std::string expected = ": error: " + message;
    if (line.compare(i, expected.size(), expected) == 0) return true;
  }
  return false;
}

inline Printed printed(const Diagnostics& diags, const SourceMap& sources) {
  return {render_text(diags, sources, {.show_source_line = false}), diags};
}

// The runtime's calls with their errors printed (the same calls, with a
// SourceMap and Diagnostics of their own).
inline Result<Scene, Printed> load_scene(const std::string& path) {
  SourceMap sources;
  Diagnostics diags;
  Result<Scene> scene = runtime::load_scene(path, sources, diags);
  if (!scene) return unexpected(printed(diags, sources));
  return std::move(*scene);
}
inline Result<Scene, Printed> parse_scene(const std::string& text, const std::string& path) {
  SourceMap sources;
  Diagnostics diags;
  Result<Scene> scene = runtime::parse_scene(text, path, sources, diags);
  if (!scene) return unexpected(printed(diags, sources));
  return std::move(*scene);
}
inline Result<RenderedFrame, Printed> render_scene(Context& context, const Scene& scene, const RenderOptions& options) {
  SourceMap sources;
  Diagnostics diags;
  Result<RenderedFrame> frame = runtime::render_scene(context, scene, options, sources, diags);
  if (!frame) return unexpected(printed(diags, sources));
  return std::move(*frame);
}
inline Result<std::unique_ptr<Renderer>, Printed> create_renderer(Context& context, RendererOptions options) {
  Diagnostics diags;
  Result<std::unique_ptr<Renderer>> renderer = Renderer::create(context, std::move(options), diags);
  if (!renderer) return unexpected(printed(diags, {}));
  return std::move(*renderer);
}
inline Result<void, Printed> render(Renderer& renderer, const Scene& scene, RenderedFrame& out,
                                    const FrameOptions& options = {}) {
  SourceMap sources;
  Diagnostics diags;
  if (!renderer.render(scene, out, options, sources, diags)) return unexpected(printed(diags, sources));
  return {};
}

inline std::string example_shader(const std::string& name) {
  return std::string(FACET_SOURCE_DIR) + "/examples/shaders/" + name;
}

// examples/scenes/<name>, loaded (a failure fails the test).
inline Scene example_scene(const std::string& name) {
  auto scene = load_scene(std::string(FACET_SOURCE_DIR) + "/examples/scenes/" + name);
  EXPECT_TRUE(scene) << scene.error().message;
  return scene ? *scene : Scene{};
}

// `count` cubes of examples/shaders/<shader> in rows of four, under one
// directional light: a scene as an engine builds it in code.
inline Scene lit_cubes(const std::string& shader, int count, int width, int height) {
  Scene scene;
  scene.path = "cubes";
  scene.width = width;
  scene.height = height;
  scene.camera.transform.position = {0, 0.5f, -8};
  scene.camera.transform.look_at = Vec3{0, 0, 0};
  SceneLight sun;
  sun.json_path = "lights[0]";
  sun.transform.rotation = {40, -30, 0};
  scene.lights.push_back(sun);
  for (int i = 0; i < count; ++i) {
    SceneObject o;
    o.json_path = "objects[" + std::to_string(i) + "]";
    o.mesh = "cube";
    o.transform.position = {float(i % 4) * 1.5f - 2.25f, float(i / 4) * 1.5f - 1.5f, 0};
    o.transform.rotation = {30, 45, 0};
    o.material.shader = example_shader(shader);
    o.material.json_path = o.json_path + ".material";
    scene.objects.push_back(std::move(o));
  }
  return scene;
}

// `options` with the development layer, so that scenes may name .shader
// files (one compiler for the test program, as an engine would keep one).
inline RenderOptions with_compiler(RenderOptions options) {
  static const std::shared_ptr<const ShaderCompiler> compiler = make_shader_compiler();
  if (!options.shader_compiler) options.shader_compiler = compiler;
  return options;
}

// A suite that draws through Renderers on the shared context and compares
// with what render_scene draws for the same scene.
class RendererTest : public LavapipeTest {
 protected:
  static std::unique_ptr<Renderer> make_renderer() {
    auto renderer = create_renderer(context(), {.shader_compiler = with_compiler({}).shader_compiler});
    EXPECT_TRUE(renderer) << renderer.error().message;
    return renderer ? std::move(*renderer) : nullptr;
  }
  // What a renderer of its own draws for `scene`: the reference.
  static RenderedFrame fresh(const Scene& scene) {
    auto frame = render_scene(context(), scene, with_compiler({}));
    EXPECT_TRUE(frame) << frame.error().message;
    return frame ? std::move(*frame) : RenderedFrame{};
  }
};

// A folder of this process's own, so that test runs in parallel do not meet.
inline std::filesystem::path test_dir() {
  std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("facet_render_tests." + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

struct RenderOutcome {
  int code = 0;
  std::string out, err;
};

// `facet render <scene> -o <name>.png` in process, checking that nothing was
// written (the bad-input tests expect a failure).
inline RenderOutcome render_expecting_failure(const std::string& name, const std::string& scene_path) {
  std::string png = (test_dir() / (name + ".out.png")).string();
  std::filesystem::remove(png);
  std::vector<const char*> argv = {"render", scene_path.c_str(), "-o", png.c_str()};
  std::ostringstream out, err;
  RenderOutcome r;
  r.code = tool::render_command(int(argv.size()), argv.data(), out, err);
  r.out = out.str();
  r.err = err.str();
  EXPECT_FALSE(std::filesystem::exists(png)) << "an output was written for " << name;
  return r;
}

// Removes this process's folder at exit.
struct TestDirCleanup {
  ~TestDirCleanup() {
    std::error_code ec;
    std::filesystem::remove_all(
        std::filesystem::temp_directory_path() / ("facet_render_tests." + std::to_string(getpid())), ec);
  }
};
inline TestDirCleanup test_dir_cleanup;

// Writes `json` as <test_dir>/<name>.json and returns the path.
inline std::string write_scene(const std::string& name, const std::string& json) {
  std::filesystem::path dir = test_dir();
  std::filesystem::path path = dir / (name + ".json");
  std::ofstream(path) << json;
  return path.string();
}

// A 64 x 64 scene around `objects` and `lights` (JSON array texts).
inline std::string small_scene(const std::string& objects, const std::string& lights = "[]") {
  return R"({"width": 64, "height": 64,
    "camera": {"position": [0, 0, -3], "look_at": [0, 0, 0], "fov": 40, "clear_color": [0, 0, 0]},
    "lights": )" + lights + R"(, "objects": )" + objects + "}";
}

inline std::string object_json(const std::string& mesh, const std::string& shader, const std::string& extra = "",
                               const std::string& position = "[0, 0, 0]") {
  return R"({"mesh": ")" + mesh + R"(", "position": )" + position + R"(, "material": {"shader": ")" +
         example_shader(shader) + "\"" + extra + "}}";
}

// Lavapipe tests that render scene texts: `name` names the file the scene
// is written to (relative paths in it resolve there).
class RenderTest : public LavapipeTest {
 protected:
  static Result<RenderedFrame, Printed> try_render(const std::string& name, const std::string& json,
                                                   const RenderOptions& options = {}) {
    auto scene = parse_scene(json, write_scene(name, json));
    EXPECT_TRUE(scene) << scene.error().message;
    if (!scene) return unexpected(scene.error());
    return render_scene(context(), *scene, with_compiler(options));
  }
  static RenderedFrame render(const std::string& name, const std::string& json, const RenderOptions& options = {}) {
    auto frame = try_render(name, json, options);
    EXPECT_TRUE(frame) << frame.error().message;
    return frame ? std::move(*frame) : RenderedFrame{};
  }
};

// The tone-mapped sRGB colour of pixel (x, y), row 0 at the top.
inline std::array<int, 3> pixel(const RenderedFrame& f, int x, int y) {
  const uint8_t* p = &f.ldr[(size_t(y) * f.width + x) * 4];
  return {p[0], p[1], p[2]};
}

inline size_t count_draws(const RenderedFrame& frame, const std::string& light_mode, bool drawn = true) {
  size_t n = 0;
  for (const DrawRecord& d : frame.draws) n += d.drawn == drawn && d.light_mode == light_mode;
  return n;
}

}  // namespace facet::runtime::test_support

// The tests call these unqualified from facet::runtime; overloads of the
// library's functions by their argument count.
namespace facet::runtime {
using test_support::load_scene;
using test_support::parse_scene;
using test_support::render_scene;
}  // namespace facet::runtime
