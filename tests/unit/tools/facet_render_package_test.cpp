// A scene may name .facetpkg packages built by facetc instead of .shader
// files: the runtime draws their variants as built (nothing is compiled), the
// image is pixel-identical to the one rendered from the sources, and a draw
// whose keywords have no exact variant in a package is drawn with Unity's
// closest match and one warning, or is an error with --strict-variants. The
// same holds for facet-play, the runtime without the compiler.
#include <nlohmann/json.hpp>

#include <span>

#include <functional>
#include <set>
#include <tuple>

#include "facet/package.h"
#include "facetc_test_util.h"

namespace facet::tools::testing {
namespace {

using ::testing::HasSubstr;

class FacetRenderPackageTest : public FacetcTest {
 protected:
  // examples/scenes/phong_lights.json (a directional, a point and a spot
  // light over Diffuse and PhongMultiLight objects) with its shaders
  // replaced by `diffuse` and `phong`.
  void write_scene(const std::string& name, const std::string& diffuse, const std::string& phong) const {
    auto scene = nlohmann::json::parse(read_all(fs::path(FACET_SOURCE_DIR) / "examples/scenes/phong_lights.json"));
    for (auto& object : scene["objects"]) {
      std::string shader = object["material"]["shader"];
      object["material"]["shader"] = shader.find("Diffuse") != std::string::npos ? diffuse : phong;
    }
    write_all(dir_ / name, scene.dump(2));
  }

  void build_package(const std::string& shader, const std::string& out, std::vector<std::string> extra = {}) const {
    std::vector<std::string> args = {example(shader), "-o", out};
    args.insert(args.end(), extra.begin(), extra.end());
    FacetcRun run = facetc(args);
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }

  // Renders the lights scene with PhongMultiLight's package changed by
  // `edit` and written back with its checksum recomputed, as anyone can.
  FacetcRun render_edited(const std::function<void(package::Package&)>& edit) const {
    build_package("Diffuse.shader", "Diffuse.facetpkg");
    build_package("PhongMultiLight.shader", "Good.facetpkg");
    std::string bytes = read_all(dir_ / "Good.facetpkg");
    Diagnostics diags;
    auto package =
        package::read_package(std::span(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()), diags);
    EXPECT_TRUE(package);
    if (!package) return {};
    edit(*package);
    std::vector<uint8_t> edited = package::write_package(*package);
    write_all(dir_ / "Phong.facetpkg", std::string(edited.begin(), edited.end()));
    write_scene("packages.json", "Diffuse.facetpkg", "Phong.facetpkg");
    return facet_render({"packages.json", "-o", "out.png"});
  }
};

TEST_F(FacetRenderPackageTest, ASceneOfPackagesIsPixelIdenticalToTheSceneOfItsShaders) {
  build_package("Diffuse.shader", "Diffuse.facetpkg");
  build_package("PhongMultiLight.shader", "Phong.facetpkg");
  write_scene("sources.json", example("Diffuse.shader"), example("PhongMultiLight.shader"));
  write_scene("packages.json", "Diffuse.facetpkg", "Phong.facetpkg");

  FacetcRun sources = facet_render({"sources.json", "-o", "sources.png", "--validation", "--stats"});
  ASSERT_EQ(sources.exit_code, 0) << sources.err;
  FacetcRun packages = facet_render({"packages.json", "-o", "packages.png", "--validation", "--stats", "--explain"});
  ASSERT_EQ(packages.exit_code, 0) << packages.err;
  EXPECT_EQ(packages.err, "") << "every draw found its exact variant";
  EXPECT_THAT(sources.out, HasSubstr("compiled: Examples/PhongMultiLight"));
  EXPECT_THAT(packages.out, HasSubstr("variants compiled: 0,")) << "a package's variants are built already";
  EXPECT_THAT(packages.out, HasSubstr("'Examples/PhongMultiLight' pass 1 FORWARD_DELTA (ForwardAdd)"));
  std::string a = read_all(dir_ / "sources.png"), b = read_all(dir_ / "packages.png");
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(a == b) << "the two images differ";
}

// A package records the GrabPasses before each pass (format 5): the
// refraction scene of two GrabPass glasses draws from packages as from
// its shaders, grabs included.
TEST_F(FacetRenderPackageTest, GrabPassesDrawFromAPackageAsFromTheShader) {
  build_package("GrabRefraction.shader", "Grab.facetpkg");
  FacetcRun unlit = facetc({std::string(FACET_SOURCE_DIR) + "/stdlib/Shaders/Unlit/Texture.shader", "-o", "Unlit.facetpkg"});
  ASSERT_EQ(unlit.exit_code, 0) << unlit.err;
  FacetcRun dump = facetc({"--dump", "Grab.facetpkg"});
  ASSERT_EQ(dump.exit_code, 0) << dump.err;
  EXPECT_EQ(nlohmann::json::parse(dump.out)["passes"][0]["grab_before"], nlohmann::json({"_GrabTexture"}));
  auto scene = nlohmann::json::parse(read_all(fs::path(FACET_SOURCE_DIR) / "examples/scenes/grab_refraction.json"));
  auto packaged = scene;
  for (size_t i = 0; i < scene["objects"].size(); ++i) {
    const std::string shader = scene["objects"][i]["material"]["shader"];
    const bool grab = shader.find("GrabRefraction") != std::string::npos;
    scene["objects"][i]["material"]["shader"] =
        grab ? example("GrabRefraction.shader") : std::string(FACET_SOURCE_DIR) + "/stdlib/Shaders/Unlit/Texture.shader";
    packaged["objects"][i]["material"]["shader"] = grab ? "Grab.facetpkg" : "Unlit.facetpkg";
    for (auto* s : {&scene, &packaged}) {
      auto& material = (*s)["objects"][i]["material"];
      if (!material.contains("properties") || !material["properties"].contains("_MainTex")) continue;
      auto& props = material["properties"];  // the backdrop's checker, found from the test's folder
      const std::string file = props["_MainTex"]["texture"];
      props["_MainTex"]["texture"] = (fs::path(FACET_SOURCE_DIR) / "examples/textures" / fs::path(file).filename()).string();
    }
  }
  write_all(dir_ / "grab_sources.json", scene.dump(2));
  write_all(dir_ / "grab_packages.json", packaged.dump(2));
  FacetcRun sources = facet_render({"grab_sources.json", "-o", "grab_sources.png", "--validation", "--stats"});
  ASSERT_EQ(sources.exit_code, 0) << sources.err;
  FacetcRun packages = facet_render({"grab_packages.json", "-o", "grab_packages.png", "--validation", "--stats"});
  ASSERT_EQ(packages.exit_code, 0) << packages.err;
  EXPECT_THAT(packages.out, HasSubstr("GrabPass copies of the screen: 2"));
  EXPECT_THAT(packages.out, HasSubstr("variants compiled: 0,"));
  std::string a = read_all(dir_ / "grab_sources.png"), b = read_all(dir_ / "grab_packages.png");
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(a == b) << "the two images differ";
}

TEST_F(FacetRenderPackageTest, AMissingVariantIsTheClosestMatchWithOneWarningOrAStrictError) {
  // The ForwardAdd pass without its point-light variants.
  write_all(dir_ / "strip.json", R"({"strip": [{"always_off": ["POINT"], "pass": "FORWARD_DELTA"}]})");
  build_package("Diffuse.shader", "Diffuse.facetpkg");
  build_package("PhongMultiLight.shader", "Phong.facetpkg", {"--strip", "strip.json"});
  write_scene("packages.json", "Diffuse.facetpkg", "Phong.facetpkg");

  FacetcRun closest = facet_render({"packages.json", "-o", "closest.png", "--validation"});
  ASSERT_EQ(closest.exit_code, 0) << closest.err;
  const std::string miss = "facet render: warning: Phong.facetpkg: pass 1 FORWARD_DELTA: no variant for {POINT}; "
                           "drawn with Unity's closest match {";
  EXPECT_THAT(closest.err, HasSubstr(miss));
  size_t first = closest.err.find(miss);
  EXPECT_EQ(closest.err.find(miss, first + 1), std::string::npos) << "two objects miss the same variant: one warning";

  FacetcRun strict = facet_render({"packages.json", "-o", "strict.png", "--strict-variants"});
  EXPECT_EQ(strict.exit_code, 1);
  EXPECT_THAT(strict.err, HasSubstr("POINT")) << strict.err;
  EXPECT_FALSE(fs::exists(dir_ / "strict.png"));
}

// A package keeps the pass's keyword_rule pragmas, so that draw-time
// selection applies `implies` as it does for the shader: a material with
// A_ON draws the A_ON B_ON variant from either.
TEST_F(FacetRenderPackageTest, KeywordRulesSelectTheSameVariantFromAPackage) {
  write_all(dir_ / "Implies.shader", R"(Shader "Test/Implies" {
  SubShader { Pass {
    CGPROGRAM
    #pragma vertex vert
    #pragma fragment frag
    #pragma shader_feature _ A_ON
    #pragma shader_feature _ B_ON
    #pragma keyword_rule implies A_ON B_ON
    #include "UnityCG.cginc"
    float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
    float4 frag() : SV_Target {
      float4 c = float4(0.2, 0.2, 0.2, 1);
    #ifdef A_ON
      c.r = 1;
    #endif
    #ifdef B_ON
      c.g = 1;
    #endif
      return c;
    }
    ENDCG
  } }
}
)");
  write_all(dir_ / "tri.obj", "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n");
  auto scene = [](const std::string& shader) {
    return R"({"width": 8, "height": 8, "camera": {"position": [0, 0, -3], "look_at": [0, 0, 0]},
      "objects": [{"mesh": "tri.obj", "material": {"shader": ")" + shader + R"(", "keywords": ["A_ON"]}}]})";
  };
  write_all(dir_ / "source.json", scene("Implies.shader"));
  write_all(dir_ / "package.json", scene("Implies.facetpkg"));
  FacetcRun build = facetc({"Implies.shader", "-o", "Implies.facetpkg"});
  ASSERT_EQ(build.exit_code, 0) << build.err;
  FacetcRun source = facet_render({"source.json", "-o", "source.png", "--explain"});
  ASSERT_EQ(source.exit_code, 0) << source.err;
  FacetcRun package = facet_render({"package.json", "-o", "package.png", "--explain", "--strict-variants"});
  ASSERT_EQ(package.exit_code, 0) << package.err;
  EXPECT_THAT(source.out, HasSubstr("variant: A_ON B_ON\n"));
  EXPECT_THAT(package.out, HasSubstr("variant: A_ON B_ON\n"));
  EXPECT_TRUE(read_all(dir_ / "source.png") == read_all(dir_ / "package.png"));
}

TEST_F(FacetRenderPackageTest, ACorruptPackageIsAnErrorNamingTheFile) {
  build_package("Diffuse.shader", "Diffuse.facetpkg");
  std::string bytes = read_all(dir_ / "Diffuse.facetpkg");
  write_all(dir_ / "Phong.facetpkg", bytes.substr(0, bytes.size() / 2));
  write_scene("packages.json", "Diffuse.facetpkg", "Phong.facetpkg");
  FacetcRun run = facet_render({"packages.json", "-o", "out.png"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("Phong.facetpkg: ")) << run.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.png"));
}

// The checksum's seed is public: a package edited and re-checksummed reads
// well. Its reflection's bindings size the driver's tables (binding 2^31
// made lavapipe allocate 240 GB and abort): one past what facetc numbers is
// a clear error.
TEST_F(FacetRenderPackageTest, AnEditedPackageWithAnAbsurdBindingIsAnErrorNotAnAbort) {
  FacetcRun run = render_edited([](package::Package& package) {
    for (package::PackagePass& pass : package.passes) {
      for (package::PackageVariant& variant : pass.variants) {
        for (package::PackageStage& stage : variant.stages) {
          for (UniformBlock& block : stage.reflection.uniform_blocks) block.binding = 2147483648u;
        }
      }
    }
  });
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("has binding 2147483648 and 1 descriptors (at most 1023 and 4096): the package's "
                                 "reflection is not facetc's"));
  EXPECT_FALSE(fs::exists(dir_ / "out.png"));
}

// Two bytes of an edited module crashed lavapipe inside vkCreateGraphicsPipelines:
// `facet render` (which has the compiler) runs spirv-val over a package's
// modules before the driver sees them.
TEST_F(FacetRenderPackageTest, AnEditedPackageWithInvalidSpirvIsAnErrorNotACrash) {
  FacetcRun run = render_edited([](package::Package& package) {
    ASSERT_FALSE(package.spirv_blobs.empty());
    for (std::vector<uint32_t>& module : package.spirv_blobs) {
      ASSERT_GT(module.size(), 6u);
      module[5] = 0xffffffffu;  // the first instruction: no opcode, a word count past the module's end
    }
  });
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("Phong.facetpkg: SPIR-V module "));
  EXPECT_THAT(run.err, HasSubstr(" is not valid SPIR-V, so it is not given to the driver"));
  EXPECT_FALSE(fs::exists(dir_ / "out.png"));
}

// The (pass name, sorted keywords) pairs a dumped package holds, or a
// collection lists for one shader.
using VariantPairs = std::set<std::pair<std::string, std::vector<std::string>>>;

VariantPairs package_variants(const nlohmann::json& dump) {
  VariantPairs out;
  for (const auto& pass : dump.at("passes")) {
    for (const auto& v : pass.at("variants")) {
      auto keywords = v.at("keywords").get<std::vector<std::string>>();
      std::sort(keywords.begin(), keywords.end());
      out.insert({pass.value("name", std::string()), keywords});
    }
  }
  return out;
}

VariantPairs collected_variants(const nlohmann::json& collection, const std::string& shader) {
  VariantPairs out;
  for (const auto& s : collection.at("shaders")) {
    if (s.at("shader") != shader) continue;
    for (const auto& pass : s.at("passes")) {
      for (const auto& keywords : pass.at("variants")) {
        out.insert({pass.value("name", std::string()), keywords.get<std::vector<std::string>>()});
      }
    }
  }
  return out;
}

TEST_F(FacetRenderPackageTest, AVariantCollectionBuildsExactlyTheVariantsTheSceneDraws) {
  write_scene("sources.json", example("Diffuse.shader"), example("PhongMultiLight.shader"));
  FacetcRun sources = facet_render({"sources.json", "-o", "sources.png", "--emit-variants", "variants.json"});
  ASSERT_EQ(sources.exit_code, 0) << sources.err;
  auto collection = nlohmann::json::parse(read_all(dir_ / "variants.json"));
  size_t full = 0, collected = 0;

  for (const auto& [shader, name, package] : {std::tuple{"Diffuse.shader", "Examples/Diffuse", "Diffuse.facetpkg"},
                                              std::tuple{"PhongMultiLight.shader", "Examples/PhongMultiLight",
                                                         "Phong.facetpkg"}}) {
    build_package(shader, package, {"--variants", "variants.json"});
    VariantPairs built = package_variants(nlohmann::json::parse(facetc({"--dump", package}).out));
    VariantPairs drawn = collected_variants(collection, name);
    EXPECT_FALSE(drawn.empty()) << name;
    EXPECT_EQ(built, drawn) << name << ": the package holds exactly the variants the scene draws";
    build_package(shader, std::string("full_") + package);
    full += package_variants(nlohmann::json::parse(facetc({"--dump", std::string("full_") + package}).out)).size();
    collected += built.size();
  }
  EXPECT_GT(full, collected) << "the full builds hold variants the scene does not draw";
  // PhongMultiLight's ForwardAdd pass is drawn for the point and the spot light.
  VariantPairs phong = collected_variants(collection, "Examples/PhongMultiLight");
  EXPECT_TRUE(phong.count({"FORWARD_DELTA", {"POINT"}})) << read_all(dir_ / "variants.json");
  EXPECT_TRUE(phong.count({"FORWARD_DELTA", {"SPOT"}})) << read_all(dir_ / "variants.json");

  write_scene("packages.json", "Diffuse.facetpkg", "Phong.facetpkg");
  FacetcRun packages = facet_render({"packages.json", "-o", "packages.png", "--strict-variants", "--validation"});
  ASSERT_EQ(packages.exit_code, 0) << packages.err;
  EXPECT_EQ(packages.err, "") << "no draw misses its variant";
  EXPECT_TRUE(read_all(dir_ / "sources.png") == read_all(dir_ / "packages.png")) << "the two images differ";
}

TEST_F(FacetRenderPackageTest, BadVariantCollectionsAreLocatedErrors) {
  struct Case {
    const char* json;
    const char* expected;
  };
  const Case cases[] = {
      {R"({"shaders": 3})", "expected an object with a 'shaders' array"},
      {R"({"shaders": [{"shader": "Examples/Diffuse"}]})", "shaders[0].passes: expected an array of passes"},
      {R"({"shaders": [{"shader": "Examples/Diffuse", "passes": [{"pass": "x", "variants": []}]}]})",
       "shaders[0].passes[0].pass: expected the pass's 0-based index in its SubShader"},
      {R"({"shaders": [{"shader": "Examples/Diffuse", "passes": [{"pass": 0, "variants": [[1]]}]}]})",
       "shaders[0].passes[0].variants[0][0]: expected a keyword string"},
      {R"({"shaders": [{"shader": "Examples/Other", "passes": []}]})",
       "shader 'Examples/Diffuse' is not in the variant collection (--variants)"},
      {R"({"shaders": [{"shader": "Examples/Diffuse", "passes": [{"pass": 7, "variants": [[]]}]}]})",
       "the variant collection lists pass 7 of shader 'Examples/Diffuse', which has"},
      {R"({"shaders": [{"shader": )", "variants.json:1:"},
  };
  for (const Case& c : cases) {
    write_all(dir_ / "variants.json", c.json);
    FacetcRun run = facetc({example("Diffuse.shader"), "--variants", "variants.json", "-o", "out.facetpkg"});
    EXPECT_EQ(run.exit_code, 1) << c.json;
    EXPECT_THAT(run.err, HasSubstr(c.expected)) << c.json;
    EXPECT_FALSE(fs::exists(dir_ / "out.facetpkg")) << c.json;
  }
}

// The ForwardAdd pass of PhongMultiLight's package without its point-light
// variants; the sources' scene draws them.
class OnDemandTest : public FacetRenderPackageTest {
 protected:
  void SetUp() override {
    FacetRenderPackageTest::SetUp();
    write_all(dir_ / "strip.json", R"({"strip": [{"always_off": ["POINT"], "pass": "FORWARD_DELTA"}]})");
    build_package("Diffuse.shader", "Diffuse.facetpkg");
    build_package("PhongMultiLight.shader", "Phong.facetpkg", {"--strip", "strip.json"});
    write_scene("packages.json", "Diffuse.facetpkg", "Phong.facetpkg");
  }
  static std::string shader_dir() { return (fs::path(FACET_SOURCE_DIR) / "examples/shaders").string(); }
  const std::string miss_ = "facet render: warning: Phong.facetpkg: pass 1 FORWARD_DELTA: no variant for {POINT}; ";
};

TEST_F(OnDemandTest, AVariantThePackageLacksIsCompiledFromTheShaderOfThatName) {
  write_scene("sources.json", example("Diffuse.shader"), example("PhongMultiLight.shader"));
  FacetcRun sources = facet_render({"sources.json", "-o", "sources.png", "--validation"});
  ASSERT_EQ(sources.exit_code, 0) << sources.err;

  FacetcRun run = facet_render(
      {"packages.json", "-o", "packages.png", "--validation", "--stats", "--explain", "--shader-dir", shader_dir()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::string compiled_from = miss_ + "compiled on demand from " + shader_dir();
  EXPECT_THAT(run.err, HasSubstr(compiled_from)) << run.err;
  EXPECT_EQ(run.err.find(compiled_from, run.err.find(compiled_from) + 1), std::string::npos) << "one warning a miss";
  EXPECT_THAT(run.out, HasSubstr("variants compiled: 1,")) << "only the point light's variant is compiled";
  EXPECT_THAT(run.out, HasSubstr("compiled on demand from")) << "--explain says why";
  std::string a = read_all(dir_ / "sources.png"), b = read_all(dir_ / "packages.png");
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(a == b) << "the exact variant is drawn, as from the sources";
}

TEST_F(OnDemandTest, WithoutTheShaderTheClosestMatchIsDrawnAndTheWarningSaysWhy) {
  fs::create_directories(dir_ / "empty");
  FacetcRun run = facet_render({"packages.json", "-o", "closest.png", "--shader-dir", "empty"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.err, HasSubstr(miss_ + "drawn with Unity's closest match {"));
  EXPECT_THAT(run.err, HasSubstr("(no .shader in the shader folders declares 'Examples/PhongMultiLight')"));
}

TEST_F(OnDemandTest, StrictSelectionCompilesNothing) {
  FacetcRun run = facet_render({"packages.json", "-o", "strict.png", "--strict-variants", "--shader-dir", shader_dir()});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("POINT")) << run.err;
  EXPECT_FALSE(fs::exists(dir_ / "strict.png"));
}

TEST_F(OnDemandTest, AShaderOfThatNameWithOtherPassesIsAnError) {
  fs::create_directories(dir_ / "other");
  write_all(dir_ / "other/Impostor.shader", R"(Shader "Examples/PhongMultiLight" {
  SubShader { Pass { Name "ONLY"
    CGPROGRAM
    #pragma vertex vert
    #pragma fragment frag
    float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
    float4 frag() : SV_Target { return 1; }
    ENDCG
  } }
})");
  FacetcRun run = facet_render({"packages.json", "-o", "impostor.png", "--shader-dir", "other"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("has no pass named 'FORWARD_DELTA' with LightMode 'ForwardAdd': it is not the "
                                 "shader the package was built from"))
      << run.err;
  EXPECT_FALSE(fs::exists(dir_ / "impostor.png"));
}

// Two unnamed passes without LightMode: the package's second pass is
// compiled from the shader's second, not from the first of that name.
TEST_F(OnDemandTest, PassesOfOneNameAreMatchedByTheirRank) {
  fs::create_directories(dir_ / "two");
  auto pass = [](const std::string& colour, const std::string& state) {
    return "  Pass { " + state + R"(
    CGPROGRAM
    #pragma vertex vert
    #pragma fragment frag
    #pragma multi_compile __ ADD_BLUE
    #include "UnityCG.cginc"
    float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
    fixed4 frag() : SV_Target {
      fixed4 c = )" + colour + R"(;
    #ifdef ADD_BLUE
      c.b = 1;
    #endif
      return c;
    }
    ENDCG
  }
)";
  };
  write_all(dir_ / "two/TwoPasses.shader", "Shader \"Tests/TwoPasses\" {\n SubShader {\n" +
                                               pass("fixed4(1, 0, 0, 1)", "") +
                                               pass("fixed4(0, 1, 0, 1)", "Blend One One ZTest LEqual") + " }\n}\n");
  // The package holds pass 0 with ADD_BLUE and pass 1 without it.
  write_all(dir_ / "collection.json", R"({"shaders": [{"shader": "Tests/TwoPasses", "passes": [
    {"pass": 0, "variants": [["ADD_BLUE"]]}, {"pass": 1, "variants": [[]]}]}]})");
  FacetcRun built = facetc({"two/TwoPasses.shader", "--variants", "collection.json", "-o", "Two.facetpkg"});
  ASSERT_EQ(built.exit_code, 0) << built.err;
  auto scene = [](const std::string& shader) {
    return R"({"width": 32, "height": 32, "camera": {"position": [0, 0, -3], "look_at": [0, 0, 0], "fov": 40},
      "objects": [{"mesh": "cube", "material": {"shader": ")" + shader + R"(", "keywords": ["ADD_BLUE"]}}]})";
  };
  write_all(dir_ / "sources.json", scene("two/TwoPasses.shader"));
  write_all(dir_ / "package.json", scene("Two.facetpkg"));
  FacetcRun sources = facet_render({"sources.json", "-o", "sources.png", "--validation"});
  ASSERT_EQ(sources.exit_code, 0) << sources.err;
  FacetcRun package = facet_render({"package.json", "-o", "package.png", "--validation", "--shader-dir", "two"});
  ASSERT_EQ(package.exit_code, 0) << package.err;
  EXPECT_THAT(package.err, HasSubstr("Two.facetpkg: pass 1: no variant for {ADD_BLUE}; compiled on demand from"));
  std::string a = read_all(dir_ / "sources.png"), b = read_all(dir_ / "package.png");
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(a == b) << "the second pass drew the first pass's code";
}

TEST_F(OnDemandTest, AShaderFolderThatIsNoFolderIsAnError) {
  FacetcRun run = facet_render({"packages.json", "-o", "x.png", "--shader-dir", "missing"});
  EXPECT_NE(run.exit_code, 0);
  EXPECT_THAT(run.err, HasSubstr("missing"));
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

TEST_F(FacetRenderPackageTest, EmittedVariantsNameImageEffectPassesByTheirIndex) {
  fs::path scene = fs::path(FACET_SOURCE_DIR) / "examples/scenes/post_chain.json";
  FacetcRun run = facet_render({scene.string(), "-o", "post.png", "--emit-variants", "post.json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json collection = nlohmann::json::parse(read_all(dir_ / "post.json"));
  VariantPairs effects = collected_variants(collection, "Hidden/Examples/ImageEffects");
  EXPECT_EQ(effects, (VariantPairs{{"GREYSCALE", {}}, {"BLUR", {}}}));
  for (const auto& s : collection.at("shaders")) {
    if (s["shader"] != "Hidden/Examples/ImageEffects") continue;
    for (const auto& pass : s["passes"]) EXPECT_EQ(pass["pass"], pass["name"] == "GREYSCALE" ? 0 : 1);
  }
}

TEST_F(FacetRenderPackageTest, EmittingVariantsNeedsTheScenesShaderFiles) {
  build_package("Diffuse.shader", "Diffuse.facetpkg");
  write_scene("mixed.json", "Diffuse.facetpkg", example("PhongMultiLight.shader"));
  FacetcRun run = facet_render({"mixed.json", "-o", "mixed.png", "--emit-variants", "mixed.variants.json"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("--emit-variants needs the scene's .shader files, not the package 'Diffuse.facetpkg'"));
  EXPECT_FALSE(fs::exists(dir_ / "mixed.png"));
  EXPECT_FALSE(fs::exists(dir_ / "mixed.variants.json"));
}

TEST_F(FacetRenderPackageTest, VariantsAndPassAreNotGivenTogether) {
  write_all(dir_ / "variants.json", R"({"shaders": [{"shader": "Examples/Diffuse", "passes": []}]})");
  FacetcRun run = facetc({example("Diffuse.shader"), "--variants", "variants.json", "--pass", "0", "-o", "d.facetpkg"});
  EXPECT_NE(run.exit_code, 0);
  EXPECT_THAT(run.err, HasSubstr("--variants chooses the passes to build; give no --pass with it"));
  EXPECT_FALSE(fs::exists(dir_ / "d.facetpkg"));
}

#ifdef FACET_PLAY_PATH
// facet-play is the runtime alone (facet_render, no compiler): it draws
// packages and links nothing that compiles shaders.
class FacetPlayTest : public FacetRenderPackageTest {
 protected:
  FacetcRun facet_play(const std::vector<std::string>& args) const {
    return run(FACET_PLAY_PATH, args, "ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 ");
  }
  // What of the compiler's libraries `program` links: its shared libraries
  // (readelf) and the symbols linked into it (nm), one line each.
  std::vector<std::string> compiler_parts(const std::string& program) const {
    FacetcRun needed = run("readelf", {"-d", program});
    EXPECT_EQ(needed.exit_code, 0) << needed.err;
    FacetcRun symbols = run("nm", {"-C", program});
    EXPECT_EQ(symbols.exit_code, 0) << symbols.err;
    std::vector<std::string> found;
    std::istringstream lines(needed.out + symbols.out);
    for (std::string line; std::getline(lines, line);) {
      for (const char* part : {"glslang", "SPIRV", "spirv_cross", "spv::", "libtbb", "tbb::", "libcurl", "curl_easy",
                               "libssl", "libcrypto", "facet::Compiler::", "facet::backend::"}) {
        if (line.find(part) != std::string::npos) {
          found.push_back(line);
          break;
        }
      }
    }
    return found;
  }
};

TEST_F(FacetPlayTest, LinksNoCompilerLibrary) {
  std::vector<std::string> play = compiler_parts(FACET_PLAY_PATH);
  EXPECT_TRUE(play.empty()) << play.size() << " compiler symbols or libraries, the first: " << play.front();
  // The same reading of `facet`, which links the development layer, finds them.
  EXPECT_FALSE(compiler_parts(FACET_PATH).empty());
}

TEST_F(FacetPlayTest, RendersASceneOfPackagesPixelIdenticalToTheSceneOfItsShaders) {
  build_package("Diffuse.shader", "Diffuse.facetpkg");
  build_package("PhongMultiLight.shader", "Phong.facetpkg");
  write_scene("sources.json", example("Diffuse.shader"), example("PhongMultiLight.shader"));
  write_scene("packages.json", "Diffuse.facetpkg", "Phong.facetpkg");

  FacetcRun sources = facet_render({"sources.json", "-o", "sources.png", "--validation"});
  ASSERT_EQ(sources.exit_code, 0) << sources.err;
  FacetcRun play = facet_play({"packages.json", "-o", "play.png", "--validation"});
  ASSERT_EQ(play.exit_code, 0) << play.err;
  EXPECT_EQ(play.err, "") << "every draw found its exact variant, and validation reported nothing";
  EXPECT_THAT(play.out, HasSubstr("variants compiled: 0"));
  std::string a = read_all(dir_ / "sources.png"), b = read_all(dir_ / "play.png");
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(a == b) << "the two images differ";
}

// The renderer's own stdlib shaders (the procedural sky, the screen-space
// shadow pass, the deferred light pass) are built into facet_render as
// packages: the runtime alone draws a deferred frame with a sky and a
// shadowed sun as the development layer does from their .shader files.
TEST_F(FacetPlayTest, DrawsTheSkyScreenSpaceShadowsAndDeferredLightsFromItsBuiltInPackages) {
  build_package("SurfaceStandard.shader", "Standard.facetpkg");
  auto scene = [](const std::string& shader) {
    std::string object = R"(, "material": {"shader": ")" + shader + R"(", "properties": {"_Glossiness": 0.3}}})";
    return R"({"width": 64, "height": 48,
      "camera": {"position": [0, 2, -4], "look_at": [0, 0.3, 0], "clear": "sky", "rendering_path": "deferred"},
      "ambient": {"sky": {"zenith": [0.3, 0.45, 0.8], "horizon": [0.8, 0.8, 0.8], "ground": [0.3, 0.25, 0.2]}},
      "lights": [{"type": "directional", "rotation": [50, 30, 0], "shadows": "hard"}],
      "objects": [{"mesh": "plane", "scale": 0.5)" + object + R"(, {"mesh": "sphere", "position": [0, 0.6, 0])" +
           object + "]}";
  };
  write_all(dir_ / "sources.json", scene(example("SurfaceStandard.shader")));
  write_all(dir_ / "packages.json", scene("Standard.facetpkg"));
  FacetcRun sources = facet_render({"sources.json", "-o", "sources.png", "--validation", "--stats"});
  ASSERT_EQ(sources.exit_code, 0) << sources.err;
  EXPECT_THAT(sources.out, HasSubstr("deferred: 2 G-buffer draws, 1 light draws"));
  EXPECT_THAT(sources.out, HasSubstr("screen-space shadow masks: 1"));
  FacetcRun play = facet_play({"packages.json", "-o", "play.png", "--validation"});
  ASSERT_EQ(play.exit_code, 0) << play.err;
  EXPECT_EQ(play.err, "");
  EXPECT_THAT(play.out, HasSubstr("variants compiled: 0"));
  std::string a = read_all(dir_ / "sources.png"), b = read_all(dir_ / "play.png");
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(a == b) << "the two images differ";
}

TEST_F(FacetPlayTest, AShaderInTheSceneIsAnErrorNamingIt) {
  build_package("Diffuse.shader", "Diffuse.facetpkg");
  write_scene("mixed.json", "Diffuse.facetpkg", example("PhongMultiLight.shader"));
  FacetcRun play = facet_play({"mixed.json", "-o", "mixed.png"});
  EXPECT_EQ(play.exit_code, 1);
  EXPECT_THAT(play.err, HasSubstr(example("PhongMultiLight.shader") + ": a .shader needs the development layer"));
  EXPECT_THAT(play.err, HasSubstr("draws packages only"));
  EXPECT_FALSE(fs::exists(dir_ / "mixed.png"));
}

TEST_F(FacetPlayTest, StrictVariantsMakeAMissingVariantAnError) {
  write_all(dir_ / "strip.json", R"({"strip": [{"always_off": ["POINT"], "pass": "FORWARD_DELTA"}]})");
  build_package("Diffuse.shader", "Diffuse.facetpkg");
  build_package("PhongMultiLight.shader", "Phong.facetpkg", {"--strip", "strip.json"});
  write_scene("packages.json", "Diffuse.facetpkg", "Phong.facetpkg");

  FacetcRun closest = facet_play({"packages.json", "-o", "closest.png"});
  ASSERT_EQ(closest.exit_code, 0) << closest.err;
  EXPECT_THAT(closest.err, HasSubstr("facet-play: warning: Phong.facetpkg: pass 1 FORWARD_DELTA: no variant for {POINT}"));
  FacetcRun strict = facet_play({"packages.json", "-o", "strict.png", "--strict-variants"});
  EXPECT_EQ(strict.exit_code, 1);
  EXPECT_THAT(strict.err, HasSubstr("POINT"));
  EXPECT_FALSE(fs::exists(dir_ / "strict.png"));
}

TEST_F(FacetPlayTest, RefusesAnOutputThatIsTheScene) {
  build_package("Diffuse.shader", "Diffuse.facetpkg");
  build_package("PhongMultiLight.shader", "Phong.facetpkg");
  write_scene("packages.json", "Diffuse.facetpkg", "Phong.facetpkg");
  std::string before = read_all(dir_ / "packages.json");
  FacetcRun play = facet_play({"packages.json", "-o", "packages.json"});
  EXPECT_EQ(play.exit_code, 1);
  EXPECT_THAT(play.err, HasSubstr("facet-play: error: output 'packages.json' is also an input of this render (the scene)"));
  EXPECT_EQ(read_all(dir_ / "packages.json"), before);
}
#endif

}  // namespace
}  // namespace facet::tools::testing
