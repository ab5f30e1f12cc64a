// The lighting-model table: well formed, one row per id, and the two forms of
// a row (the point form the stability suite and the GPU cases evaluate, the
// parameter form facet brdf and the accuracy study integrate) the same model.
#include "facet/reference/models.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>

#include "facet/reference/lighting.h"

namespace facet::reference {
namespace {

using glm::dvec3;

TEST(ReferenceModelsTest, IdsAndNamesAreUniqueAndEveryRowHasAForm) {
  std::set<std::string> ids, names;
  ASSERT_FALSE(lighting_models().empty());
  for (const LightingModel& m : lighting_models()) {
    SCOPED_TRACE(m.id);
    EXPECT_FALSE(m.id.empty());
    EXPECT_TRUE(ids.insert(m.id).second);
    EXPECT_TRUE(names.insert(m.name).second);
    EXPECT_FALSE(m.stdlib.empty());
    EXPECT_EQ(m.hlsl.empty(), !m.cpu) << "a point form has both its HLSL and its twin";
    EXPECT_TRUE(!m.hlsl.empty() || m.bind);
    EXPECT_EQ(m.params.empty(), !m.bind);
    if (!m.hlsl.empty()) {
      // The first function the row names is the one its HLSL calls.
      std::string first = m.stdlib.substr(0, m.stdlib.find_first_of(" *("));
      EXPECT_NE(m.hlsl.find(first + "("), std::string::npos) << first;
    }
    for (const ModelParam& p : m.params) {
      for (int i = 0; i < 3; ++i) {
        EXPECT_GE(p.default_value[i], p.min) << p.name;
        EXPECT_LE(p.default_value[i], p.max) << p.name;
      }
    }
  }
}

TEST(ReferenceModelsTest, LookupsNameTheMissingRowOrParameter) {
  EXPECT_EQ(find_lighting_model("no-such-model"), nullptr);
  ASSERT_NE(find_lighting_model("ggx"), nullptr);
  EXPECT_THROW(model_brdf("no-such-model"), std::out_of_range);
  EXPECT_THROW(model_brdf("translucency"), std::out_of_range);  // no parameter form
  EXPECT_THROW(model_brdf("ggx", {{"sigma", dvec3(1.0)}}), std::out_of_range);
  EXPECT_EQ(model_params(*find_lighting_model("ggx")).num("roughness"), 0.5);
}

// Parameters of the parameter form that make it the point form's model at
// (roughness r, f0), per the rows' own comments; empty where the forms differ
// by design (ggx-ms: E estimated against integrated).
std::map<std::string, dvec3> params_at(const std::string& id, double r, double f0) {
  double alpha = FacetClampAlpha(r * r);
  if (id == "lambert") return {{"albedo", dvec3(1.0)}};
  if (id == "burley" || id == "frostbite") return {{"roughness", dvec3(r)}, {"albedo", dvec3(1.0)}};
  if (id == "oren-nayar" || id == "oren-nayar-qualitative") return {{"sigma", dvec3(r)}, {"albedo", dvec3(1.0)}};
  if (id == "phong" || id == "blinn-phong") return {{"exponent", dvec3(FacetAlphaToBlinnPhongExponent(alpha))}};
  if (id == "ggx" || id == "beckmann" || id == "ggx-separable" || id == "ggx-schlick" || id == "ggx-karis")
    return {{"roughness", dvec3(r)}, {"f0", dvec3(f0)}};
  if (id == "ward") return {{"alpha_x", dvec3(alpha)}, {"alpha_y", dvec3(alpha)}, {"ks", dvec3(1.0)}};
  if (id.rfind("unity-brdf", 0) == 0) return {{"albedo", dvec3(1.0)}, {"metallic", dvec3(f0)}, {"smoothness", dvec3(1 - r)}};
  if (id == "disney")
    return {{"baseColor", dvec3(1.0)}, {"subsurface", dvec3(0.5)}, {"metallic", dvec3(f0)}, {"roughness", dvec3(r)},
            {"anisotropic", dvec3(0.5)}, {"sheen", dvec3(1.0)},   {"clearcoat", dvec3(1.0)}};
  return {};
}

TEST(ReferenceModelsTest, ThePointAndParameterFormsOfARowAgreeInTheLocalFrame) {
  int compared = 0;
  for (const LightingModel& m : lighting_models()) {
    if (m.hlsl.empty() || !m.bind) continue;
    for (double r : {0.3, 0.6, 0.9}) {
      const double f0 = 0.3;
      std::map<std::string, dvec3> params = params_at(m.id, r, f0);
      if (params.empty()) continue;
      LocalBrdf f = m.bind(model_params(m, params));
      for (double theta_v : {0.1, 0.7, 1.2}) {
        for (double theta_l : {0.2, 0.9}) {
          ModelPoint p;
          p.v = {std::sin(theta_v), 0, std::cos(theta_v)};
          p.l = {-std::sin(theta_l) * 0.6, std::sin(theta_l) * 0.8, std::cos(theta_l)};
          p.roughness = r, p.f0 = f0;
          dvec3 point = m.cpu(p);
          dvec3 param = f(p.v, p.l) * p.l.z * (m.unity ? kPi : 1.0);
          for (int i = 0; i < 3; ++i) EXPECT_NEAR(point[i], param[i], 1e-9 * (1 + std::abs(point[i]))) << m.id << " r=" << r;
          ++compared;
        }
      }
    }
  }
  EXPECT_GE(compared, 15 * 3 * 6);  // every row with both forms but ggx-ms
}

}  // namespace
}  // namespace facet::reference
