// facetc --scene: the renderer says which passes and keyword sets a scene
// draws; facetc builds each .shader the scene names with exactly those, and
// the scene drawn from the packages (facet render --packages) is the scene
// drawn from its sources, with no variant missing.
#include <nlohmann/json.hpp>

#include <map>
#include <set>

#include "facetc_test_util.h"

namespace facet::tools::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// Shader name -> pass index -> sorted keyword sets.
using Variants = std::map<std::string, std::map<size_t, std::set<std::vector<std::string>>>>;

Variants collection_variants(const nlohmann::json& collection) {
  Variants out;
  for (const auto& shader : collection["shaders"]) {
    for (const auto& pass : shader["passes"]) {
      for (const auto& set : pass["variants"]) {
        out[shader["shader"]][pass["pass"]].insert(set.get<std::vector<std::string>>());
      }
    }
  }
  return out;
}

class FacetcSceneTest : public FacetcTest {
 protected:
  // facetc, its renderer child without LeakSanitizer's exit check (see facet_render).
  FacetcRun facetc_scene(const std::vector<std::string>& args) const {
    return run(FACETC_PATH, args, "ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 ");
  }

  // What `package` holds, as facetc --dump reads it: its passes by their
  // SubShader index, each with its variants' sorted keywords.
  Variants package_variants(const std::string& package) const {
    FacetcRun dump = facetc({package, "--dump"});
    EXPECT_EQ(dump.exit_code, 0) << dump.err;
    auto j = nlohmann::json::parse(dump.out);
    Variants out;
    for (const auto& pass : j["passes"]) {
      for (const auto& v : pass["variants"]) {
        std::vector<std::string> keywords = v["keywords"].get<std::vector<std::string>>();
        std::sort(keywords.begin(), keywords.end());
        out[j["shader"]["name"]][pass["index"]].insert(keywords);
      }
    }
    return out;
  }
};

// shadows.json: a directional light with screen-space shadows and a spot
// light over a Standard surface shader and an alpha-tested one, so the
// collection has ForwardBase, ForwardAdd and ShadowCaster passes, and the
// renderer's own screen-space shadow shader, which is not built.
TEST_F(FacetcSceneTest, BuildsExactlyTheVariantsTheSceneDrawsAndTheSceneDrawsFromThemWithNoMiss) {
  const std::string scene = std::string(FACET_SOURCE_DIR) + "/examples/scenes/shadows.json";
  FacetcRun built = facetc_scene({"--scene", scene, "--out-dir", "packages"});
  ASSERT_EQ(built.exit_code, 0) << built.err;
  auto collection = nlohmann::json::parse(read_all(dir_ / "packages/shadows.variants.json"));
  Variants wanted = collection_variants(collection);
  ASSERT_TRUE(wanted.count("Hidden/Internal-ScreenSpaceShadows")) << "the collection lists every draw";

  size_t packages = 0;
  for (const auto& shader : collection["shaders"]) {
    if (!shader.contains("source")) continue;  // the renderer's own
    const std::string name = shader["shader"];
    fs::path package = dir_ / "packages" / fs::path(shader["source"].get<std::string>()).stem();
    package += ".facetpkg";
    ASSERT_TRUE(fs::exists(package)) << package;
    Variants held = package_variants(package.string());
    EXPECT_EQ(held[name], wanted[name]) << name << ": the package holds exactly the passes and variants drawn";
    EXPECT_TRUE(held[name].count(0) && held[name].count(1)) << name << ": its ForwardBase and ForwardAdd passes";
    ++packages;
  }
  EXPECT_EQ(packages, 2u);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "packages"), fs::directory_iterator()), 3)
      << "two packages and the collection, nothing else";

  FacetcRun sources = facet_render({scene, "-o", "sources.png"});
  ASSERT_EQ(sources.exit_code, 0) << sources.err;
  FacetcRun drawn = facet_render({scene, "--packages", "packages", "--strict-variants", "-o", "packages.png",
                                  "--stats", "--explain", "--validation"});
  ASSERT_EQ(drawn.exit_code, 0) << drawn.err;
  EXPECT_EQ(drawn.err, "") << "no variant missed";
  EXPECT_THAT(drawn.out, Not(HasSubstr("compiled: Examples/"))) << "the scene's shaders came from the packages";
  EXPECT_TRUE(read_all(dir_ / "sources.png") == read_all(dir_ / "packages.png")) << "the two images differ";
}

// Image effects name their pass by its SubShader index; a package of only
// the passes a chain uses keeps those indices (package format 6).
TEST_F(FacetcSceneTest, AnImageEffectDrawsItsPassFromAPackageOfSomePasses) {
  const std::string scene = std::string(FACET_SOURCE_DIR) + "/examples/scenes/post_depth.json";
  FacetcRun built = facetc_scene({"--scene", scene, "--out-dir", "packages"});
  ASSERT_EQ(built.exit_code, 0) << built.err;
  FacetcRun sources = facet_render({scene, "-o", "sources.png"});
  ASSERT_EQ(sources.exit_code, 0) << sources.err;
  FacetcRun drawn = facet_render({scene, "--packages", "packages", "--strict-variants", "-o", "packages.png"});
  ASSERT_EQ(drawn.exit_code, 0) << drawn.err;
  EXPECT_TRUE(read_all(dir_ / "sources.png") == read_all(dir_ / "packages.png")) << "the two images differ";
}

TEST_F(FacetcSceneTest, ASceneThatDoesNotRenderBuildsNothing) {
  write_all(dir_ / "broken.json", R"({"camera": {}, "objects": [{"mesh": "cube", "material": {"shader": "missing.shader"}}]})");
  FacetcRun built = facetc_scene({"--scene", "broken.json", "--out-dir", "packages"});
  EXPECT_EQ(built.exit_code, 1);
  EXPECT_THAT(built.err, HasSubstr("missing.shader"));
  EXPECT_THAT(built.err, HasSubstr("nothing was built"));
  EXPECT_FALSE(fs::exists(dir_ / "packages" / "broken.variants.json"));
}

TEST_F(FacetcSceneTest, SceneTakesNoInputsOrVariantChoices) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"--scene", "s.json", example("Unlit.shader")},
        std::vector<std::string>{"--scene", "s.json", "-o", "x.facetpkg"},
        std::vector<std::string>{"--scene", "s.json", "--keywords", "A"},
        std::vector<std::string>{"--scene", "s.json", "-E"}}) {
    FacetcRun run = facetc(args);
    EXPECT_EQ(run.exit_code, 2) << args.back();
    EXPECT_THAT(run.err, HasSubstr("--scene")) << args.back();
  }
}

// A scene file named as a package of one of its shaders would be replaced by it.
TEST_F(FacetcSceneTest, NoPackageMayReplaceTheScene) {
  nlohmann::json scene = {{"camera", nlohmann::json::object()},
                          {"objects", {{{"mesh", "cube"}, {"material", {{"shader", example("Unlit.shader")}}}}}}};
  write_all(dir_ / "Unlit.facetpkg", scene.dump());
  FacetcRun built = facetc_scene({"--scene", "Unlit.facetpkg", "--out-dir", "."});
  EXPECT_EQ(built.exit_code, 1);
  EXPECT_THAT(built.err, HasSubstr("is also an input"));
  EXPECT_EQ(read_all(dir_ / "Unlit.facetpkg"), scene.dump());
}

}  // namespace
}  // namespace facet::tools::testing
