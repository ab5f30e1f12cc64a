// The accuracy-versus-cost study: its errors agree with the measured anchors
// of docs/accuracy.md ("Agreement with the measured anchors"), every row compiles and is counted, the GPU
// pass times every row on lavapipe, and the reports hold what they claim.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <nlohmann/json.hpp>
#include <sstream>

#include "facet/runtime/accuracy.h"
#include "unit/runtime/context_fixture.h"  // keeps lavapipe mapped for LeakSanitizer

namespace facet::runtime::accuracy {
namespace {

const std::vector<StudyRow>& errors() {
  static const std::vector<StudyRow> rows = compute_errors();
  return rows;
}

const StudyRow& row(const std::string& id) {
  for (const StudyRow& r : errors()) {
    if (r.id == id) return r;
  }
  throw std::runtime_error("no row " + id);
}

TEST(AccuracyStudyTest, HasAtLeast25RowsWithAnError) {
  size_t measured = std::count_if(errors().begin(), errors().end(), [](const StudyRow& r) { return r.metric != "-"; });
  EXPECT_GE(measured, 25u);
  for (const StudyRow& r : errors()) {
    EXPECT_TRUE(std::isfinite(r.error) || r.id == "D_GGX_fp16") << r.id;
    EXPECT_FALSE(r.group.empty() || r.name.empty() || r.reference.empty()) << r.id;
  }
}

// Each anchor of docs/accuracy.md that the study reproduces, with
// the tolerance its quadrature or grid allows (docs/accuracy.md).
TEST(AccuracyStudyTest, ErrorsAgreeWithTheMeasuredAnchors) {
  struct Anchor {
    const char* id;
    double value, tolerance;
  };
  for (const Anchor& a : std::initializer_list<Anchor>{
           {"F_Schlick", 0.036, 0.003},          // eta = 1.5
           {"F_SchlickSG", 0.0038, 0.0004},
           {"F_Pow4", 0.082, 0.003},
           {"Fd_Burley", 0.519, 0.02},            // albedo 1.519
           {"BlinnPhongNormalized", 0.075, 0.01},  // albedo 1.075 at n = 10
           {"PhongNormalized", 0.0, 0.005},
           {"CookTorranceGGX", 1 - 0.409, 0.02},   // E_avg 0.409 at a = 1
           {"SRGBPow22", 0.0335, 0.002},
           {"Unity_BRDF2_SurfaceReduction", 0.020, 0.002},
           {"CookTorranceGGX_Compensated", 0.0, 0.01},
       }) {
    EXPECT_NEAR(row(a.id).error, a.value, a.tolerance) << a.id << ": " << row(a.id).detail;
  }
  EXPECT_LE(row("EnvBRDFApprox").error, 0.41);
  EXPECT_GT(row("EnvBRDFApprox").error, 0.1);
  EXPECT_LE(row("Unity_SurfaceReduction").error, 0.40);
  // fp16: the naive GGX D is far off where documented, the cross-product form is not.
  EXPECT_GT(row("D_GGX_fp16").error, 10.0);
  EXPECT_LT(row("D_GGX_FP16Safe").error, 0.01);
  // Hammon's fast V: relL1 <= 0.19 over the lobe.
  EXPECT_LE(row("V_SmithGGXCorrelatedFast").error, 0.2);
  EXPECT_GT(row("V_SmithGGXCorrelatedFast").error, 0.02);
}

TEST(AccuracyStudyTest, RunsEveryRowOnTheGpuWithValidationAndCountsItsInstructions) {
  (void)test_support::kLavapipePinned;
  Diagnostics diags;
  StudyOptions options{.validation = true, .width = 16, .height = 16, .evaluations = 2, .frames = 1, .image_samples = 4};
  auto study = run_study(options, diags);
  ASSERT_TRUE(study) << (diags.size() ? diags.all()[0].message : "");
  EXPECT_FALSE(study->device.empty());
  EXPECT_EQ(study->device_type, "cpu");  // lavapipe: the chart's caveat reads this
  std::map<std::string, uint32_t> counts;
  for (const StudyRow& r : study->rows) {
    ASSERT_TRUE(r.ns_per_eval.has_value()) << r.id;
    EXPECT_GE(*r.ns_per_eval, 0.0) << r.id;
    counts[r.id] = r.spirv_instructions;
  }
  // Static cost orders what it should: the exact dielectric Fresnel costs
  // more than Schlick's, the full Oren-Nayar more than the qualitative one.
  EXPECT_GT(counts["F_Dielectric"], counts["F_Schlick"]);
  EXPECT_GT(counts["Fd_OrenNayar"], counts["Fd_OrenNayarQualitative"]);
  EXPECT_GT(counts["V_SmithGGXCorrelated"], counts["V_SmithGGXCorrelatedFast"]);

  nlohmann::json j = nlohmann::json::parse(study_json(*study));
  EXPECT_EQ(j["rows"].size(), study->rows.size());
  std::string html = study_html(*study);
  EXPECT_EQ(size_t(std::count(html.begin(), html.end(), '\n')) > study->rows.size(), true);
  // This pass is tiny, so on lavapipe a row's time minus the null pass is
  // often 0 and then it has no point on the chart; the page says so.
  bool chartable = std::any_of(study->rows.begin(), study->rows.end(), [](const StudyRow& r) {
    return r.error > 0 && std::isfinite(r.error) && r.ns_per_eval && *r.ns_per_eval > 0;
  });
  EXPECT_EQ(html.find("class=\"pareto\"") != std::string::npos, chartable);
  EXPECT_EQ(html.find("No row has both an error and a GPU time") != std::string::npos, !chartable);
  // With times, every row with an error is a point of the chart, in its
  // error kind's panel and in the image panel.
  Study timed = *study;
  size_t with_error = 0;
  for (size_t i = 0; i < timed.rows.size(); ++i) {
    timed.rows[i].ns_per_eval = 1.0 + double(i);
    with_error += timed.rows[i].error > 0 && std::isfinite(timed.rows[i].error);
    // and in the image panel, where its image error is finite and above 0
    const ImageError* worst = worst_image_error(timed.rows[i]);
    with_error += worst && worst->rmse > 0 && std::isfinite(worst->rmse);
  }
  std::string chart = study_html(timed);
  EXPECT_NE(chart.find("class=\"pareto\""), std::string::npos);
  size_t points = 0;
  for (size_t at = chart.find("class=\"point\""); at != std::string::npos; at = chart.find("class=\"point\"", at + 1)) ++points;
  EXPECT_EQ(points, with_error);
}

// The fp16 columns: the rows' HLSL and the stdlib in real 16-bit arithmetic
// on lavapipe (shaderFloat16), against their fp64 twins.
TEST(AccuracyStudyTest, FillsTheFp16ColumnsWithRealHalfArithmeticOnLavapipe) {
  (void)test_support::kLavapipePinned;
  Diagnostics diags;
  StudyOptions options{.validation = true, .width = 16, .height = 16, .evaluations = 2, .frames = 1};
  auto study = run_study(options, diags);
  ASSERT_TRUE(study) << (diags.size() ? diags.all()[0].message : "");
  ASSERT_TRUE(study->shader_float16.has_value());
  if (!*study->shader_float16) GTEST_SKIP() << study->device << " has no shaderFloat16";
  std::map<std::string, const StudyRow*> by_id;
  for (const StudyRow& r : study->rows) by_id[r.id] = &r;
  const char* half_rows[] = {"D_GGX_fp16", "D_GGX_FP16Safe", "V_SmithGGXCorrelated", "V_SmithGGXCorrelatedFast",
                             "V_SmithGGXSeparable", "V_SchlickGGX", "V_SchlickGGXKaris", "F_Schlick", "F_SchlickSG",
                             "Fd_Burley"};
  for (const char* id : half_rows) {
    ASSERT_TRUE(by_id.count(id)) << id;
    const StudyRow& r = *by_id[id];
    ASSERT_TRUE(r.fp16_error.has_value()) << id;
    ASSERT_TRUE(r.fp16_ns_per_eval.has_value()) << id;
    EXPECT_GE(*r.fp16_ns_per_eval, 0.0) << id;
    EXPECT_FALSE(r.fp16_domain.empty()) << id;
    std::printf("[ fp16 study ] %-26s fp16 error %-10.4g ns/eval %.4g (fp32 %.4g)\n", id, *r.fp16_error,
                *r.fp16_ns_per_eval, r.ns_per_eval.value_or(-1));
  }
  // The naive GGX D fails in real half where the CPU _Float16 row says it
  // does; the cross-product form holds the CPU row's budget.
  const StudyRow& naive = *by_id["D_GGX_fp16"];
  EXPECT_TRUE(std::isinf(*naive.fp16_error) || *naive.fp16_error > 1.0) << *naive.fp16_error;
  const StudyRow& safe = *by_id["D_GGX_FP16Safe"];
  EXPECT_TRUE(std::isfinite(*safe.fp16_error));
  EXPECT_LE(*safe.fp16_error, 0.01);
  // V and Schlick F lose little in half off grazing (the _Float16 tests: <= 1 %).
  for (const char* id : {"V_SmithGGXCorrelated", "V_SmithGGXCorrelatedFast", "F_Schlick"}) {
    EXPECT_LE(*by_id[id]->fp16_error, 0.01) << id;
  }
  for (const StudyRow& r : study->rows) {
    if (std::find_if(std::begin(half_rows), std::end(half_rows), [&](const char* id) { return r.id == id; }) != std::end(half_rows)) continue;
    EXPECT_FALSE(r.fp16_error || r.fp16_ns_per_eval) << r.id << " is not evaluated in half";
  }
  // The columns reach the JSON and the page.
  nlohmann::json j = nlohmann::json::parse(study_json(*study));
  EXPECT_EQ(j["shader_float16"], true);
  std::string html = study_html(*study);
  EXPECT_NE(html.find("<th>fp16 GPU error</th><th>fp16 ns/eval</th>"), std::string::npos);
}

TEST(AccuracyCommandTest, WritesTheReportAndRejectsBadArguments) {
  (void)test_support::kLavapipePinned;
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / ("facet_accuracy_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ostringstream out, err;
  EXPECT_EQ(run_accuracy_command({"--out", (dir / "r.json").string(), "--no-gpu", "--image-samples", "4"}, out, err), 0) << err.str();
  EXPECT_TRUE(fs::exists(dir / "r.json"));
  EXPECT_FALSE(fs::exists(dir / "r.json.tmp"));
  EXPECT_EQ(run_accuracy_command({"--out", (dir / "r.txt").string(), "--no-gpu"}, out, err), 2);
  EXPECT_NE(err.str().find("must end in .html, .json or .svg"), std::string::npos);
  EXPECT_EQ(run_accuracy_command({"--no-gpu"}, out, err), 2);
  EXPECT_EQ(run_accuracy_command({"--out", (dir / "x.html").string(), "--device", "no-such-device"}, out, err), 1);
  EXPECT_FALSE(fs::exists(dir / "x.html"));
  // --from redraws a study written before, as a chart alone or a page.
  EXPECT_EQ(run_accuracy_command({"--from", (dir / "r.json").string(), "--out", (dir / "c.svg").string()}, out, err), 0)
      << err.str();
  EXPECT_EQ(run_accuracy_command({"--from", (dir / "missing.json").string(), "--out", (dir / "d.svg").string()}, out, err), 1);
  EXPECT_NE(err.str().find("cannot read"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "d.svg"));
  fs::remove_all(dir);
}

// The H200 study of docs/figures, as the docs' chart draws it.
Study h200() {
  std::ifstream in(std::string(FACET_SOURCE_DIR) + "/docs/figures/accuracy-h200.json");
  std::stringstream text;
  text << in.rdbuf();
  Result<Study> study = study_from_json(text.str());
  EXPECT_TRUE(study) << (study ? "" : study.error().reason);
  return study ? *study : Study{};
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// (Not designated initialisers: GCC 12 then warns that options.device may be uninitialised.)
Study on_device(const std::string& device, const std::string& type = "") {
  Study s;
  s.device = device, s.device_type = type;
  return s;
}

TEST(AccuracyChartTest, EveryRowWithAnErrorHasAnErrorKind) {
  for (const StudyRow& r : errors()) {
    EXPECT_EQ(error_kind(r) == ErrorKind::none, r.metric == "-") << r.id << ": " << r.metric;
  }
  EXPECT_EQ(error_kind(row("V_SchlickGGX")), ErrorKind::lobe);
  EXPECT_EQ(error_kind(row("Fd_Burley")), ErrorKind::energy);
  EXPECT_EQ(error_kind(row("CookTorranceGGX_Compensated")), ErrorKind::energy);
  EXPECT_EQ(error_kind(row("F_Schlick")), ErrorKind::pointwise);
  EXPECT_EQ(error_kind(row("EnvBRDFApprox")), ErrorKind::pointwise);
  EXPECT_EQ(error_kind(row("D_GGX_FP16Safe")), ErrorKind::fp16);
}

TEST(AccuracyChartTest, StudiesRoundTripThroughJson) {
  Study s = on_device("llvmpipe (LLVM 15.0.6, 256 bits)", "cpu");
  s.rows = errors();
  s.rows[1].ns_per_eval = 0.25;
  Result<Study> back = study_from_json(study_json(s));
  ASSERT_TRUE(back);
  EXPECT_EQ(back->device, s.device);
  EXPECT_EQ(back->device_type, "cpu");
  ASSERT_EQ(back->rows.size(), s.rows.size());
  for (size_t i = 0; i < s.rows.size(); ++i) {
    EXPECT_EQ(back->rows[i].id, s.rows[i].id);
    EXPECT_EQ(back->rows[i].metric, s.rows[i].metric);
    EXPECT_EQ(back->rows[i].error, s.rows[i].error) << s.rows[i].id;  // inf too
    EXPECT_EQ(back->rows[i].ns_per_eval, s.rows[i].ns_per_eval);
  }
  // The fp16 columns round-trip, an overflow included; a study without them
  // (written before them) reads with them empty.
  s.shader_float16 = true;
  s.rows[0].fp16_error = 0.0035, s.rows[0].fp16_ns_per_eval = 0.5, s.rows[0].fp16_domain = "NoV in [0.01, 1]";
  s.rows[1].fp16_error = std::numeric_limits<double>::infinity();
  Result<Study> with_fp16 = study_from_json(study_json(s));
  ASSERT_TRUE(with_fp16);
  EXPECT_EQ(with_fp16->shader_float16, std::optional<bool>(true));
  EXPECT_EQ(with_fp16->rows[0].fp16_error, 0.0035);
  EXPECT_EQ(with_fp16->rows[0].fp16_ns_per_eval, 0.5);
  EXPECT_EQ(with_fp16->rows[0].fp16_domain, "NoV in [0.01, 1]");
  EXPECT_TRUE(with_fp16->rows[1].fp16_error && std::isinf(*with_fp16->rows[1].fp16_error));
  EXPECT_FALSE(with_fp16->rows[2].fp16_error || with_fp16->rows[2].fp16_ns_per_eval);
  EXPECT_FALSE(back->shader_float16.has_value());
  Result<Study> old = study_from_json(R"({"device": "NVIDIA H200", "rows": [{"id": "F_Schlick", "error": 0.036, "ns_per_eval": 0.25}]})");
  ASSERT_TRUE(old);
  EXPECT_FALSE(old->rows[0].fp16_error || old->rows[0].fp16_ns_per_eval || old->shader_float16);
  EXPECT_NE(study_html(*with_fp16).find("inf (overflow)</td><td class=\"n\">-</td></tr>"), std::string::npos);

  EXPECT_FALSE(study_from_json("[1, 2]"));
  EXPECT_FALSE(study_from_json("{\"rows\": [{\"group\": \"V\"}]}"));
}

TEST(AccuracyChartTest, TimesFromACpuImplementationAreRecognised) {
  EXPECT_TRUE(timed_on_cpu(on_device("anything", "cpu")));
  EXPECT_FALSE(timed_on_cpu(on_device("llvmpipe", "discrete-gpu")));
  EXPECT_TRUE(timed_on_cpu(on_device("llvmpipe (LLVM 15.0.6, 256 bits)")));  // older studies: no type recorded
  EXPECT_TRUE(timed_on_cpu(on_device("SwiftShader Device (LLVM 10.0.0)")));
  EXPECT_FALSE(timed_on_cpu(on_device("NVIDIA H200")));
}

// An image panel, then one panel per error kind; every timed row with a
// finite error a point in its family's colour (once in its kind's panel and
// once in the image panel when it has an image error), the overflowing row
// named instead, and the caveat only for a CPU device.
TEST(AccuracyChartTest, DrawsOnePanelPerErrorKindColouredByFamily) {
  Study study = h200();
  ASSERT_FALSE(study.rows.empty());
  std::string svg = study_chart_svg(study);
  std::set<ErrorKind> kinds;
  for (const StudyRow& r : study.rows)
    if (error_kind(r) != ErrorKind::none) kinds.insert(error_kind(r));  // reference rows have no panel
  EXPECT_EQ(count(svg, "class=\"panel-title\""), 1 + kinds.size());
  EXPECT_NE(svg.find("Image error: RMSE in the worst test scene"), std::string::npos);
  auto timed = [](const StudyRow& r) { return r.ns_per_eval && *r.ns_per_eval > 0; };
  size_t drawable = std::count_if(study.rows.begin(), study.rows.end(), [&](const StudyRow& r) {
    return r.error > 0 && std::isfinite(r.error) && timed(r);
  });
  size_t imaged = std::count_if(study.rows.begin(), study.rows.end(), [&](const StudyRow& r) {
    const ImageError* worst = worst_image_error(r);
    return worst && worst->rmse > 0 && std::isfinite(worst->rmse) && timed(r);
  });
  ASSERT_GT(imaged, 0u);
  EXPECT_EQ(count(svg, "class=\"point\""), drawable + imaged);
  EXPECT_EQ(count(svg, "class=\"label\""), drawable + imaged);
  // A label that does not fit at its point is numbered and named in the
  // legend: the numbers run 1, 2, ... and each names a drawn row.
  size_t entries = count(svg, "class=\"legend\"");
  for (size_t n = 1; n <= entries; ++n) {
    std::string entry = "class=\"legend\">" + std::to_string(n) + ": ";
    size_t at = svg.find(entry);
    ASSERT_NE(at, std::string::npos) << n;
    std::string id = svg.substr(at + entry.size(), svg.find('<', at) - at - entry.size());
    EXPECT_NE(svg.find("data-id=\"" + id + "\""), std::string::npos) << id;
  }
  EXPECT_NE(svg.find("not drawn: D_GGX_fp16 (inf: overflow)"), std::string::npos);
  EXPECT_EQ(svg.find("class=\"caveat\""), std::string::npos);
  for (auto [id, colour] : {std::pair{"V_SchlickGGX", "#1f77b4"}, {"F_Schlick", "#ff7f0e"}, {"Fd_Burley", "#2ca02c"},
                            {"BRDF2_Unity_PBS", "#9467bd"}, {"EnvBRDFApprox", "#17becf"}}) {
    size_t at = svg.find(std::string("data-id=\"") + id + "\"");
    ASSERT_NE(at, std::string::npos) << id;
    size_t tag = svg.rfind("<path", at);
    EXPECT_NE(svg.substr(tag, at - tag).find(std::string("stroke=\"") + colour + "\""), std::string::npos) << id;
  }
  // In the lobe panel (after the image panel, so a row's last point) Hammon's
  // fast V is Pareto-optimal (filled); the separable V, dearer and further
  // off than it, is dominated (hollow).
  auto fill_of = [&](const std::string& id) {
    size_t at = svg.rfind("data-id=\"" + id + "\"");
    size_t fill = svg.rfind("fill=\"", at);
    return svg.substr(fill + 6, 7);
  };
  EXPECT_EQ(fill_of("V_SmithGGXCorrelatedFast"), "#1f77b4");
  EXPECT_EQ(fill_of("V_SmithGGXSeparable"), "#ffffff");
  study.device = "llvmpipe (LLVM 15.0.6, 256 bits)";
  study.device_type = "cpu";
  std::string cpu = study_chart_svg(study);
  EXPECT_NE(cpu.find("class=\"caveat\""), std::string::npos);
  EXPECT_NE(cpu.find("times measured on lavapipe, a CPU implementation of Vulkan: relative only"), std::string::npos);
  EXPECT_EQ(study_chart_svg(study), cpu);  // deterministic
  // Without times there is no chart, and the SVG says why.
  for (StudyRow& r : study.rows) r.ns_per_eval.reset();
  std::string none = study_chart_svg(study);
  EXPECT_EQ(none.find("class=\"pareto\""), std::string::npos);
  EXPECT_NE(none.find("No row has both an error and a GPU time"), std::string::npos);
}

}  // namespace
}  // namespace facet::runtime::accuracy
