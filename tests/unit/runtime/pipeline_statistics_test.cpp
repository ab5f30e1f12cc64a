// Driver statistics (VK_KHR_pipeline_executable_properties): the decoding of
// each value format and the costs found by name, on hand-made statistics as
// NVIDIA, RADV and ANV name them; and on lavapipe, which does not offer the
// extension, that asking for them is no error and capturing them is refused.
#include "facet/runtime/pipeline_statistics.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>

#include "facet/runtime/compute.h"
#include "facet/runtime/vulkan_context.h"
#include "unit/runtime/context_fixture.h"

namespace facet::runtime {
namespace {

VkPipelineExecutableStatisticKHR statistic(const char* name, VkPipelineExecutableStatisticFormatKHR format) {
  VkPipelineExecutableStatisticKHR s{VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_STATISTIC_KHR};
  std::strncpy(s.name, name, VK_MAX_DESCRIPTION_SIZE - 1);
  std::strncpy(s.description, "made by the test", VK_MAX_DESCRIPTION_SIZE - 1);
  s.format = format;
  return s;
}
VkPipelineExecutableStatisticKHR u64(const char* name, uint64_t value) {
  auto s = statistic(name, VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_UINT64_KHR);
  s.value.u64 = value;
  return s;
}
VkPipelineExecutableStatisticKHR i64(const char* name, int64_t value) {
  auto s = statistic(name, VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_INT64_KHR);
  s.value.i64 = value;
  return s;
}
VkPipelineExecutableStatisticKHR f64(const char* name, double value) {
  auto s = statistic(name, VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_FLOAT64_KHR);
  s.value.f64 = value;
  return s;
}
VkPipelineExecutableStatisticKHR b32(const char* name, bool value) {
  auto s = statistic(name, VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR);
  s.value.b32 = value ? VK_TRUE : VK_FALSE;
  return s;
}

PipelineExecutable executable(const char* name, std::vector<VkPipelineExecutableStatisticKHR> statistics) {
  return {.name = name, .stages = VK_SHADER_STAGE_COMPUTE_BIT, .statistics = decode_statistics(statistics)};
}

TEST(PipelineStatisticsDecodeTest, EachFormatReadsItsOwnUnionMember) {
  EXPECT_EQ(statistic_value(u64("a", 18446744073709551615ull)), 18446744073709551615.0);
  EXPECT_EQ(statistic_value(u64("a", 42)), 42.0);
  EXPECT_EQ(statistic_value(i64("a", -7)), -7.0);
  EXPECT_EQ(statistic_value(f64("a", 0.375)), 0.375);
  EXPECT_EQ(statistic_value(b32("a", true)), 1.0);
  EXPECT_EQ(statistic_value(b32("a", false)), 0.0);
  // A format this API version does not define is not guessed at.
  auto unknown = statistic("a", VkPipelineExecutableStatisticFormatKHR(7));
  unknown.value.u64 = 5;
  EXPECT_EQ(statistic_value(unknown), std::nullopt);
}

TEST(PipelineStatisticsDecodeTest, KeepsOrderTrimsNamesAndDropsUnknownFormats) {
  auto unknown = statistic("Mystery", VkPipelineExecutableStatisticFormatKHR(7));
  std::vector<DriverStatistic> decoded =
      decode_statistics(std::vector{u64("  Register Count ", 40), unknown, f64("Occupancy", 0.5), b32("Spills", false)});
  ASSERT_EQ(decoded.size(), 3u);
  EXPECT_EQ(decoded[0].name, "Register Count");
  EXPECT_EQ(decoded[0].value, 40.0);
  EXPECT_EQ(decoded[1].name, "Occupancy");
  EXPECT_EQ(decoded[2].name, "Spills");
  EXPECT_EQ(decoded[2].format, VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR);
}

TEST(PipelineStatisticsDecodeTest, ANameFillingTheWholeArrayIsReadWithoutItsMissingNul) {
  VkPipelineExecutableStatisticKHR s = u64("", 1);
  std::memset(s.name, 'x', VK_MAX_DESCRIPTION_SIZE);  // no terminating NUL
  std::vector<DriverStatistic> decoded = decode_statistics(std::vector{s});
  ASSERT_EQ(decoded.size(), 1u);
  EXPECT_EQ(decoded[0].name.size(), size_t(VK_MAX_DESCRIPTION_SIZE));
}

TEST(PipelineStatisticsCostsTest, NvidiaNamesGiveRegistersAndCodeBytes) {
  std::vector<PipelineExecutable> nvidia{
      executable("Compute Shader", {u64("Register Count", 16), u64("Binary Size", 1536), u64("Stack Size", 0)})};
  DriverCosts costs = driver_costs(nvidia);
  EXPECT_EQ(costs.registers, 16u);
  EXPECT_EQ(costs.code_bytes, 1536u);
  EXPECT_EQ(costs.instructions, std::nullopt);
}

TEST(PipelineStatisticsCostsTest, RadvNamesGiveVectorRegistersInstructionsAndCodeSize) {
  std::vector<PipelineExecutable> radv{executable(
      "Compute Shader", {u64("Driver pipeline hash", 123456789), u64("SGPRs", 24), u64("VGPRs", 12),
                         u64("Spilled SGPRs", 0), u64("Spilled VGPRs", 0), u64("Code size", 412), u64("Instructions", 97),
                         u64("Pre-Sched VGPRs", 10)})};
  DriverCosts costs = driver_costs(radv);
  EXPECT_EQ(costs.registers, 12u);  // VGPRs, not SGPRs, not the spilled or pre-scheduling counts
  EXPECT_EQ(costs.instructions, 97u);
  EXPECT_EQ(costs.code_bytes, 412u);
}

TEST(PipelineStatisticsCostsTest, AnvNamesOldAndNewAreBothRead) {
  std::vector<PipelineExecutable> old_anv{
      executable("SIMD16 Compute Shader", {u64("Instruction Count", 120), u64("SEND Count", 3), u64("Cycle Count", 900)})};
  EXPECT_EQ(driver_costs(old_anv).instructions, 120u);
  std::vector<PipelineExecutable> new_anv{
      executable("SIMD16 Compute Shader", {u64("Instructions", 118), u64("Code size", 1888), u64("GRF registers", 64)})};
  DriverCosts costs = driver_costs(new_anv);
  EXPECT_EQ(costs.instructions, 118u);
  EXPECT_EQ(costs.code_bytes, 1888u);
  EXPECT_EQ(costs.registers, 64u);
}

TEST(PipelineStatisticsCostsTest, NamesCompareWithoutCaseButWholeAndTheFirstListedNameWins) {
  std::vector<PipelineExecutable> e{
      executable("cs", {u64("instruction count", 50), u64("INSTRUCTIONS", 40), u64("register count", 8),
                        u64("Registers", 9), u64("binary size", 64), u64("Instructions per clock", 3)})};
  DriverCosts costs = driver_costs(e);
  EXPECT_EQ(costs.instructions, 40u);  // "Instructions" is listed before "Instruction Count"
  EXPECT_EQ(costs.registers, 8u);      // "Register Count" before "Registers"
  EXPECT_EQ(costs.code_bytes, 64u);
  // Only whole names: a statistic that merely contains a cost's name is no cost.
  DriverCosts none = driver_costs(std::vector{executable("cs", {u64("Spilled VGPRs", 4), u64("Max live registers", 30)})});
  EXPECT_EQ(none.registers, std::nullopt);
  EXPECT_EQ(none.instructions, std::nullopt);
  EXPECT_EQ(none.code_bytes, std::nullopt);
}

TEST(PipelineStatisticsCostsTest, OtherFormatsCountWhenTheyAreCountsAndBoolsNever) {
  DriverCosts costs = driver_costs(std::vector{
      executable("cs", {i64("Instructions", 33), f64("Register Count", 20.0), b32("Binary Size", true)})});
  EXPECT_EQ(costs.instructions, 33u);
  EXPECT_EQ(costs.registers, 20u);
  EXPECT_EQ(costs.code_bytes, std::nullopt);
  DriverCosts bad = driver_costs(std::vector{
      executable("cs", {i64("Instructions", -1), f64("Register Count", std::numeric_limits<double>::quiet_NaN())})});
  EXPECT_EQ(bad.instructions, std::nullopt);
  EXPECT_EQ(bad.registers, std::nullopt);
}

TEST(PipelineStatisticsCostsTest, SeveralExecutablesSumInstructionsAndTakeTheLargestRegisterCount) {
  std::vector<PipelineExecutable> two{executable("Vertex Shader", {u64("Instructions", 30), u64("VGPRs", 8)}),
                                      executable("Fragment Shader", {u64("Instructions", 70), u64("VGPRs", 24)})};
  DriverCosts costs = driver_costs(two);
  EXPECT_EQ(costs.instructions, 100u);
  EXPECT_EQ(costs.registers, 24u);
  EXPECT_EQ(driver_costs(std::vector<PipelineExecutable>{}).instructions, std::nullopt);
}

class PipelineStatisticsLavapipeTest : public ::testing::Test {};

// lavapipe (Mesa 22.3) does not offer the extension: the context comes up
// without it, pipelines that would capture statistics are refused with a
// reason, and nothing reaches the validation layer.
TEST_F(PipelineStatisticsLavapipeTest, AskingOnADeviceWithoutTheExtensionIsNoError) {
  (void)test_support::kLavapipePinned;
  VkResultOf<std::unique_ptr<Context>> context = create_context({.validation = true, .pipeline_statistics = true});
  ASSERT_TRUE(context) << describe(context.error());
  EXPECT_FALSE((*context)->device_info().pipeline_executable_info) << (*context)->device_info().name;
  EXPECT_FALSE((*context)->pipeline_statistics());
  VkResultOf<std::vector<PipelineExecutable>> statistics = pipeline_statistics(**context, VK_NULL_HANDLE);
  ASSERT_FALSE(statistics);
  EXPECT_EQ(statistics.error().code, VkErrorCode::invalid_argument);
  std::vector<uint32_t> not_used{0x07230203u, 0x00010300u, 0, 1, 0};
  VkResultOf<ComputePipeline> pipeline =
      create_compute_pipeline(**context, not_used, {.storage_buffers = 1, .capture_statistics = true});
  ASSERT_FALSE(pipeline);
  EXPECT_EQ(pipeline.error().code, VkErrorCode::invalid_argument);
  EXPECT_NE(describe(pipeline.error()).find("VK_KHR_pipeline_executable_properties"), std::string::npos);
  EXPECT_TRUE((*context)->messages().empty()) << (*context)->messages_text();
}

}  // namespace
}  // namespace facet::runtime
