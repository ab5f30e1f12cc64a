// Bad scenes through `facet render`: each kind of mistake gives one clear
// message naming the file and the JSON path, exit code 1, and no output file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "facet/commands.h"
#include "render_test_support.h"

namespace facet::runtime {
namespace {

using test_support::object_json;
using test_support::small_scene;
using test_support::write_scene;

struct Outcome {
  int code = 0;
  std::string out, err;
};

Outcome facet_render(const std::vector<std::string>& args) {
  std::vector<const char*> argv = {"render"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  std::ostringstream out, err;
  Outcome r;
  r.code = tool::render_command(int(argv.size()), argv.data(), out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

std::string output_path(const std::string& name) {
  return (test_support::test_dir() / (name + ".png")).string();
}

// "line:column" of the first `text` in `json`: where a located error points.
std::string place_of(const std::string& json, const std::string& text) {
  size_t at = json.find(text), line = 1, column = 1;
  for (size_t i = 0; i < at && i < json.size(); ++i) {
    if (json[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

Outcome render_bad(const std::string& name, const std::string& json) {
  std::string png = output_path(name);
  std::filesystem::remove(png);
  Outcome r = facet_render({write_scene(name, json), "-o", png});
  EXPECT_FALSE(std::filesystem::exists(png)) << "an output was written for a bad scene";
  return r;
}

TEST(SceneErrors, MissingSceneFileNamesTheFile) {
  Outcome r = facet_render({"/nonexistent/scene.json", "-o", output_path("missing")});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("/nonexistent/scene.json: cannot open the scene file"), std::string::npos) << r.err;
}

TEST(SceneErrors, InvalidJsonNamesLineAndColumn) {
  Outcome r = render_bad("syntax", "{\n  \"width\": 64,\n  \"camera\": {,\n}");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("syntax.json:3:14: error: invalid JSON"), std::string::npos) << r.err;
}

TEST(SceneErrors, ColourWithTheWrongNumberOfNumbersNamesTheJsonPath) {
  std::string objects = "[" + object_json("sphere", "Unlit.shader") + ", " +
                        object_json("sphere", "Unlit.shader", R"(, "properties": {"_Color": [1, 0]})") + "]";
  std::string json = small_scene(objects);
  Outcome r = render_bad("bad_color", json);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("bad_color.json:" + place_of(json, "[1, 0]") +
                       ": error: objects[1].material.properties._Color: expected 4 numbers"),
            std::string::npos)
      << r.err;
}

TEST(SceneErrors, UnknownShaderPropertySuggestsTheClosestName) {
  std::string objects = "[" + object_json("sphere", "Unlit.shader", R"(, "properties": {"_Colr": [1, 0, 0, 1]})") + "]";
  std::string json = small_scene(objects);
  Outcome r = render_bad("unknown_property", json);
  EXPECT_EQ(r.code, 1);
  // Found when the renderer binds the material, and still located in the scene file.
  EXPECT_NE(r.err.find("unknown_property.json:" + place_of(json, "[1, 0, 0, 1]") +
                       ": error: objects[0].material.properties._Colr: the shader 'Examples/Unlit' has no property "
                       "'_Colr' (did you mean '_Color'?)"),
            std::string::npos)
      << r.err;
}

TEST(SceneErrors, WrongTypeOfAFieldNamesItsPath) {
  std::string json = small_scene("[" + object_json("sphere", "Unlit.shader") + "]");
  json.insert(1, R"("time": "noon", )");
  Outcome r = render_bad("wrong_type", json);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("wrong_type.json:" + place_of(json, "\"noon\"") + ": error: time: expected a number"),
            std::string::npos)
      << r.err;
}

TEST(SceneErrors, MissingShaderFileNamesThePath) {
  std::string json = small_scene(R"([{"mesh": "cube", "material": {"shader": "no/such.shader"}}])");
  Outcome r = render_bad("missing_shader", json);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("objects[0].material.shader: shader file"), std::string::npos) << r.err;
}

TEST(SceneErrors, UnknownMeshAndUnknownKeyAreErrors) {
  Outcome mesh = render_bad("bad_mesh", small_scene(R"([{"mesh": "teapot", "material": {"shader": "x"}}])"));
  EXPECT_EQ(mesh.code, 1);
  EXPECT_NE(mesh.err.find("objects[0].mesh: not a built-in mesh"), std::string::npos) << mesh.err;
  std::string json = small_scene("[" + object_json("sphere", "Unlit.shader") + "]");
  json.insert(1, R"("widht": 64, )");
  Outcome key = render_bad("bad_key", json);
  EXPECT_EQ(key.code, 1);
  EXPECT_NE(key.err.find("bad_key.json:" + place_of(json, "64") + ": error: widht: unknown key"), std::string::npos)
      << key.err;
}

TEST(SceneErrors, UnknownLightTypeListsTheChoices) {
  Outcome r = render_bad("bad_light", small_scene("[" + object_json("sphere", "Unlit.shader") + "]",
                                              R"([{"type": "area"}])"));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("lights[0].type: unknown value 'area' (expected one of: directional, point, spot)"),
            std::string::npos)
      << r.err;
}

TEST(SceneErrors, UnknownLightRenderModeListsTheChoices) {
  Outcome r = render_bad("bad_render_mode", small_scene("[" + object_json("sphere", "Unlit.shader") + "]",
                                                        R"([{"type": "point", "render_mode": "Important"}])"));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("lights[0].render_mode: unknown value 'Important' (expected one of: auto, important, "
                       "not_important)"),
            std::string::npos)
      << r.err;
}

// The errors of a render through the library: facet's Diagnostics, with ids
// and spans in the caller's SourceMap.
class RenderDiagnostics : public test_support::LavapipeTest {};

TEST_F(RenderDiagnostics, AShaderThatDoesNotCompileGivesTheCompilersErrorsWhereTheyAreInTheShader) {
  const std::string shader = (test_support::test_dir() / "broken.shader").string();
  std::ofstream(shader) << "Shader \"Test/Broken\" { SubShader { Pass {\nCGPROGRAM\n#pragma vertex vert\n"
                           "#pragma fragment frag\nfloat4 vert(float4 v : POSITION) : SV_POSITION { return v; }\n"
                           "float4 frag() : SV_Target { return undefined_name; }\nENDCG\n} } }\n";
  std::string json = small_scene(R"([{"mesh": "cube", "material": {"shader": ")" + shader + R"("}}])");
  SourceMap sources;
  Diagnostics diags;
  auto scene = runtime::parse_scene(json, write_scene("broken_shader", json), sources, diags);
  ASSERT_TRUE(scene) << render_text(diags, sources);
  auto frame = runtime::render_scene(context(), *scene, test_support::with_compiler({}), sources, diags);
  ASSERT_FALSE(frame);
  ASSERT_GE(diags.size(), 2u);
  EXPECT_EQ(diags.all()[0].id, DiagId::shader_unavailable);
  EXPECT_NE(diags.all()[0].message.find("objects[0]"), std::string::npos) << diags.all()[0].message;
  bool in_shader = false;
  for (const Diagnostic& d : diags.all()) {
    if (!d.span.has_location() || sources.path(d.span.file) != shader) continue;
    in_shader = true;
    EXPECT_EQ(sources.line_column(d.span.file, d.span.begin).line, 6u) << d.message;
  }
  EXPECT_TRUE(in_shader) << render_text(diags, sources);
  EXPECT_NE(render_text(diags, sources).find("broken.shader:6:"), std::string::npos) << render_text(diags, sources);
}

TEST_F(RenderDiagnostics, AMaterialErrorIsLocatedInTheSceneFileTheCallerLoaded) {
  std::string objects = "[" + object_json("sphere", "Unlit.shader", R"(, "properties": {"_Color": "red"})") + "]";
  std::string json = small_scene(objects);
  const std::string path = write_scene("material_error", json);
  SourceMap sources;
  Diagnostics diags;
  auto scene = runtime::load_scene(path, sources, diags);
  ASSERT_TRUE(scene) << render_text(diags, sources);
  ASSERT_FALSE(runtime::render_scene(context(), *scene, test_support::with_compiler({}), sources, diags));
  ASSERT_EQ(diags.size(), 1u) << render_text(diags, sources);
  const Diagnostic& d = diags.all()[0];
  EXPECT_EQ(d.id, DiagId::scene_material_property);
  ASSERT_TRUE(d.span.has_location());
  EXPECT_EQ(sources.path(d.span.file), path);
  EXPECT_EQ(sources.file_count(), 1u);  // the scene the caller loaded, not a second copy
  EXPECT_EQ(sources.text(d.span.file).substr(d.span.begin, d.span.end - d.span.begin), "\"red\"");
}

TEST_F(RenderDiagnostics, ASceneBuiltInCodeNamesThePathWithoutAPlace) {
  Scene scene = test_support::lit_cubes("Unlit.shader", 1, 16, 16);
  scene.path = "";
  scene.objects[0].material.properties.push_back({"_Nope", "objects[0].material.properties._Nope", {1, 0, 0, 1}, {}});
  SourceMap sources;
  Diagnostics diags;
  ASSERT_FALSE(runtime::render_scene(context(), scene, test_support::with_compiler({}), sources, diags));
  ASSERT_EQ(diags.size(), 1u);
  EXPECT_FALSE(diags.all()[0].span.has_location());
  EXPECT_EQ(diags.all()[0].id, DiagId::scene_material_property);
  EXPECT_EQ(diags.all()[0].message.rfind("objects[0].material.properties._Nope: ", 0), 0u) << diags.all()[0].message;
}

TEST(SceneErrors, NoOutputRequestedIsAnError) {
  Outcome r = facet_render({write_scene("no_output", small_scene("[]"))});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("nothing to write"), std::string::npos) << r.err;
}

TEST(RenderCommand, WritesAPngWithValidationOnAndPrintsStatsAndExplain) {
  std::string png = output_path("ok");
  std::string exr = (test_support::test_dir() / "ok.exr").string();
  std::filesystem::remove(png);
  std::filesystem::remove(exr);
  Outcome r = facet_render({write_scene("ok", small_scene("[" + object_json("sphere", "Unlit.shader") + "]")), "-o", png,
                            "--exr", exr, "--validation", "--stats", "--explain"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(png));
  EXPECT_TRUE(std::filesystem::exists(exr));
  EXPECT_NE(r.out.find("draws: 1 (0 additive)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("why: no LightMode: drawn once"), std::string::npos) << r.out;
}

TEST(RenderCommand, FramesPrintsTheMedianFrameTime) {
  std::string png = output_path("frames");
  Outcome r = facet_render({write_scene("frames", small_scene("[" + object_json("sphere", "Unlit.shader") + "]")), "-o",
                            png, "--stats", "--frames", "3"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("frames: 3, frame time median"), std::string::npos) << r.out;
}

TEST(RenderCommand, FramesOutOfRangeIsAnErrorAndWritesNothing) {
  for (const char* frames : {"0", "-2", "many"}) {
    std::string png = output_path("bad_frames");
    std::filesystem::remove(png);
    Outcome r = facet_render({write_scene("bad_frames", small_scene("[]")), "-o", png, "--frames", frames});
    EXPECT_EQ(r.code, 1) << frames;
    EXPECT_NE(r.err.find("--frames"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(png));
  }
}

}  // namespace
}  // namespace facet::runtime
