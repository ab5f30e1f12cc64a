// The study's driver-statistics columns: on lavapipe (no
// VK_KHR_pipeline_executable_properties) the study runs, says so and shows no
// driver column; the fields survive the JSON round trip, older JSON without
// them still reads, and the page shows a column only where a row has data.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <unistd.h>

#include "accuracy/driver_statistics.h"
#include "facet/runtime/accuracy.h"
#include "facet/runtime/vulkan_context.h"
#include "unit/runtime/context_fixture.h"  // keeps lavapipe mapped for LeakSanitizer

namespace facet::runtime::accuracy {
namespace {

StudyRow row(const std::string& id) {
  return {.id = id, .group = "F", .name = id, .reference = "exact", .metric = "max |dF|", .error = 0.01,
          .spirv_instructions = 6, .ns_per_eval = 0.25};
}

// A study as a device with the extension would leave it: one row with all
// three costs and its raw statistics, one with registers only, one without.
Study with_driver_statistics() {
  Study study{.device = "NVIDIA H200", .device_type = "discrete-gpu"};
  StudyRow full = row("F_Schlick");
  full.driver_instructions = 12;
  full.driver_registers = 16;
  full.driver_code_bytes = 192;
  full.driver_statistics = {{"Register Count", 16}, {"Binary Size", 1728}, {"Occupancy", 0.75}};
  StudyRow registers_only = row("F_Pow4");
  registers_only.driver_registers = 10;
  registers_only.driver_statistics = {{"Register Count", 10}};
  study.rows = {full, registers_only, row("F_Dielectric")};
  study.driver_statistics_offered = true;
  return study;
}

// A study on a device that does not offer the extension.
Study without_driver_statistics(const std::string& device) {
  Study study;
  study.device = device;
  study.device_type = "cpu";
  study.rows = {row("F_Schlick")};
  study.driver_statistics_offered = false;
  return study;
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(AccuracyDriverStatisticsTest, OnLavapipeTheStudyRunsAndMarksThemUnavailable) {
  (void)test_support::kLavapipePinned;
  Diagnostics diags;
  StudyOptions options{.validation = true, .width = 8, .height = 8, .evaluations = 1, .frames = 1};
  Result<Study> study = run_study(options, diags);
  ASSERT_TRUE(study) << (diags.size() ? diags.all()[0].message : "");
  ASSERT_TRUE(study->driver_statistics_offered.has_value());
  EXPECT_FALSE(*study->driver_statistics_offered);
  for (const StudyRow& r : study->rows) {
    EXPECT_FALSE(r.driver_instructions || r.driver_registers || r.driver_code_bytes) << r.id;
    EXPECT_TRUE(r.driver_statistics.empty()) << r.id;
  }
  std::string html = study_html(*study);
  EXPECT_NE(html.find("Driver statistics: not available on " + study->device), std::string::npos);
  EXPECT_EQ(html.find("<th>driver"), std::string::npos);
  nlohmann::json j = nlohmann::json::parse(study_json(*study));
  EXPECT_EQ(j["driver_statistics_offered"], false);
  EXPECT_FALSE(j["rows"][0].contains("driver_registers"));
}

// The kernels whose statistics a driver reports are the study's own: on
// lavapipe (without the capture flag, which it cannot take) every row's and
// the null model's make a pipeline that the validation layer accepts.
TEST(AccuracyDriverStatisticsTest, EveryRowsKernelIsAValidPipeline) {
  (void)test_support::kLavapipePinned;
  VkResultOf<std::unique_ptr<Context>> context = create_context({.validation = true, .pipeline_statistics = true});
  ASSERT_TRUE(context) << describe(context.error());
  Diagnostics diags;
  Result<ComputePipeline> null_model = kernel_pipeline(**context, "", kNullModel, false, diags);
  EXPECT_TRUE(null_model) << (diags.size() ? diags.all()[0].message : null_model.error().reason);
  for (const RowSpec& spec : catalogue()) {
    Result<ComputePipeline> pipeline = kernel_pipeline(**context, spec.includes, spec.hlsl, false, diags);
    EXPECT_TRUE(pipeline) << spec.row.id << ": " << (pipeline ? "" : pipeline.error().reason);
  }
  // Capturing needs the extension, which lavapipe lacks: a clear error.
  Result<ComputePipeline> capture = kernel_pipeline(**context, "", kNullModel, true, diags);
  ASSERT_FALSE(capture);
  EXPECT_NE(capture.error().reason.find("VK_KHR_pipeline_executable_properties"), std::string::npos);
  EXPECT_TRUE((*context)->messages().empty()) << (*context)->messages_text();
}

TEST(AccuracyDriverStatisticsTest, WithoutTheGpuNothingIsRecorded) {
  Diagnostics diags;
  Result<Study> study = run_study({.gpu = false}, diags);
  ASSERT_TRUE(study) << (diags.size() ? diags.all()[0].message : "");
  EXPECT_FALSE(study->driver_statistics_offered.has_value());
  EXPECT_FALSE(nlohmann::json::parse(study_json(*study)).contains("driver_statistics_offered"));
  EXPECT_EQ(study_html(*study).find("Driver statistics"), std::string::npos);
  // The command's switch to leave them out.
  std::string out_path = (std::filesystem::temp_directory_path() / ("facet_driver_" + std::to_string(::getpid()) + ".json")).string();
  std::ostringstream out, err;
  EXPECT_EQ(run_accuracy_command({"--out", out_path, "--no-gpu", "--no-driver-statistics"}, out, err), 0) << err.str();
  std::filesystem::remove(out_path);
}

TEST(AccuracyDriverStatisticsTest, TheFieldsSurviveTheJsonRoundTrip) {
  Study study = with_driver_statistics();
  Result<Study> back = study_from_json(study_json(study));
  ASSERT_TRUE(back) << back.error().reason;
  EXPECT_EQ(back->driver_statistics_offered, true);
  ASSERT_EQ(back->rows.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    const StudyRow &a = study.rows[i], &b = back->rows[i];
    EXPECT_EQ(a.driver_instructions, b.driver_instructions) << a.id;
    EXPECT_EQ(a.driver_registers, b.driver_registers) << a.id;
    EXPECT_EQ(a.driver_code_bytes, b.driver_code_bytes) << a.id;
    EXPECT_EQ(a.driver_statistics, b.driver_statistics) << a.id;
  }
  // And a second trip writes the same text.
  EXPECT_EQ(study_json(*back), study_json(study));
}

TEST(AccuracyDriverStatisticsTest, AStudyWithoutThemWritesNoKeysAndReadsBackEmpty) {
  Study study = without_driver_statistics("llvmpipe");
  std::string text = study_json(study);
  EXPECT_EQ(text.find("\"driver_instructions\""), std::string::npos);
  EXPECT_EQ(text.find("\"driver_statistics\""), std::string::npos);
  Result<Study> back = study_from_json(text);
  ASSERT_TRUE(back) << back.error().reason;
  EXPECT_EQ(back->driver_statistics_offered, false);
  EXPECT_FALSE(back->rows[0].driver_registers.has_value());
  EXPECT_TRUE(back->rows[0].driver_statistics.empty());
}

// A study written before the driver columns existed: the committed H200
// study with every driver field taken out.
std::string older_study_json() {
  std::ifstream in(std::string(FACET_SOURCE_DIR) + "/docs/figures/accuracy-h200.json");
  nlohmann::json study = nlohmann::json::parse(in);
  study.erase("driver_statistics_offered");
  for (nlohmann::json& r : study["rows"]) {
    for (const char* key : {"driver_instructions", "driver_registers", "driver_code_bytes", "driver_statistics"}) {
      r.erase(key);
    }
  }
  return study.dump(2);
}

TEST(AccuracyDriverStatisticsTest, OlderJsonWithoutTheFieldsStillReads) {
  std::string text = older_study_json();
  ASSERT_EQ(text.find("\"driver_"), std::string::npos);
  Result<Study> study = study_from_json(text);
  ASSERT_TRUE(study) << study.error().reason;
  EXPECT_FALSE(study->driver_statistics_offered.has_value());
  ASSERT_FALSE(study->rows.empty());
  for (const StudyRow& r : study->rows) {
    EXPECT_FALSE(r.driver_instructions || r.driver_registers || r.driver_code_bytes) << r.id;
  }
  std::string html = study_html(*study);
  EXPECT_NE(html.find("Driver statistics: not recorded in this study."), std::string::npos);
  EXPECT_EQ(html.find("<th>driver"), std::string::npos);
  // Malformed driver fields are ignored, not trusted.
  Result<Study> odd = study_from_json(R"({"rows": [{"id": "x", "driver_registers": -3, "driver_statistics": [1, {"name": 2}]}],
                                          "driver_statistics_offered": "yes"})");
  ASSERT_TRUE(odd) << odd.error().reason;
  EXPECT_FALSE(odd->driver_statistics_offered.has_value());
  EXPECT_FALSE(odd->rows[0].driver_registers.has_value());
  EXPECT_TRUE(odd->rows[0].driver_statistics.empty());
}

TEST(AccuracyDriverStatisticsTest, ThePageShowsAColumnOnlyWhereARowHasItsValue) {
  Study study = with_driver_statistics();
  std::string html = study_html(study);
  EXPECT_EQ(count(html, "<th>driver instr.</th>"), 1u);
  EXPECT_EQ(count(html, "<th>driver regs</th>"), 1u);
  EXPECT_EQ(count(html, "<th>driver code bytes</th>"), 1u);
  EXPECT_NE(html.find("VK_KHR_pipeline_executable_properties on NVIDIA H200"), std::string::npos);
  EXPECT_NE(html.find("'Register Count'"), std::string::npos);  // the names read are stated
  EXPECT_NE(html.find("'Binary Size'"), std::string::npos);
  // Rows without a value show a dash: in the table F_Pow4 lacks two costs and
  // F_Dielectric three; in the raw table F_Pow4 two names, F_Dielectric three.
  EXPECT_EQ(count(html, "<td class=\"n\">—</td>"), 5u + 5u);
  EXPECT_NE(html.find("<details><summary>Driver statistics as the driver reports them"), std::string::npos);

  // Registers only: the other two columns are hidden.
  for (StudyRow& r : study.rows) r.driver_instructions.reset(), r.driver_code_bytes.reset();
  html = study_html(study);
  EXPECT_EQ(count(html, "<th>driver instr.</th>"), 0u);
  EXPECT_EQ(count(html, "<th>driver code bytes</th>"), 0u);
  EXPECT_EQ(count(html, "<th>driver regs</th>"), 1u);

  // Statistics but none of the names read: no column, and the page says so.
  for (StudyRow& r : study.rows) r.driver_registers.reset();
  html = study_html(study);
  EXPECT_EQ(html.find("<th>driver"), std::string::npos);
  EXPECT_NE(html.find("The driver reports none of these names"), std::string::npos);
}

TEST(AccuracyDriverStatisticsTest, ADeviceWithoutTheExtensionIsNamed) {
  Study study = without_driver_statistics("llvmpipe (LLVM 15.0.6, 256 bits)");
  EXPECT_NE(study_html(study).find("Driver statistics: not available on llvmpipe (LLVM 15.0.6, 256 bits)"),
            std::string::npos);
}

}  // namespace
}  // namespace facet::runtime::accuracy
