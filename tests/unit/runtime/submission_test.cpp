// The one submit-and-wait path: a Submission reused across submissions, and
// one-off submissions, on lavapipe with validation on.
#include "facet/runtime/submission.h"

#include <gtest/gtest.h>

#include <cstring>

#include "facet/runtime/buffer.h"
#include "unit/runtime/context_fixture.h"

namespace facet::runtime {
namespace {

class SubmissionTest : public test_support::LavapipeTest {
 protected:
  static uint32_t first_word(const Buffer& buffer) {
    uint32_t word = 0;
    std::memcpy(&word, buffer.data(), sizeof(word));
    return word;
  }
};

TEST_F(SubmissionTest, ASubmissionRunsEachRecordingOnItsOneCommandBuffer) {
  VkResultOf<Buffer> buffer = create_storage_buffer(context(), 256);
  ASSERT_TRUE(buffer) << describe(buffer.error());
  VkResultOf<Submission> submission = Submission::create(context());
  ASSERT_TRUE(submission) << describe(submission.error());
  VkCommandBuffer first = VK_NULL_HANDLE;
  for (uint32_t value : {7u, 11u, 13u}) {
    VkCommandBuffer used = VK_NULL_HANDLE;
    auto done = submission->submit([&](VkCommandBuffer c) {
      used = c;
      vkCmdFillBuffer(c, buffer->handle(), 0, VK_WHOLE_SIZE, value);
    });
    ASSERT_TRUE(done) << describe(done.error());
    EXPECT_EQ(first_word(*buffer), value);  // waited for: the queue has run it
    if (!first) first = used;
    EXPECT_EQ(used, first);  // reset and recorded again, not allocated anew
  }
}

TEST_F(SubmissionTest, ItSaysWhenTheSubmitReturnedBeforeTheWait) {
  VkResultOf<Submission> submission = Submission::create(context());
  ASSERT_TRUE(submission);
  const auto before = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point submitted{};
  ASSERT_TRUE(submission->submit([](VkCommandBuffer) {}, {.submitted = &submitted}));
  EXPECT_GE(submitted, before);
  EXPECT_LE(submitted, std::chrono::steady_clock::now());
}

TEST_F(SubmissionTest, AOneOffSubmissionRunsAndWaits) {
  VkResultOf<Buffer> buffer = create_storage_buffer(context(), 64);
  ASSERT_TRUE(buffer);
  auto done = submit_and_wait(context(), [&](VkCommandBuffer c) { vkCmdFillBuffer(c, buffer->handle(), 0, 64, 42u); });
  ASSERT_TRUE(done) << describe(done.error());
  EXPECT_EQ(first_word(*buffer), 42u);
}

TEST_F(SubmissionTest, AMovedSubmissionKeepsWorkingAndTheOldOneOwnsNothing) {
  VkResultOf<Buffer> buffer = create_storage_buffer(context(), 64);
  ASSERT_TRUE(buffer);
  VkResultOf<Submission> created = Submission::create(context());
  ASSERT_TRUE(created);
  Submission moved = std::move(*created);
  ASSERT_TRUE(moved.submit([&](VkCommandBuffer c) { vkCmdFillBuffer(c, buffer->handle(), 0, 64, 5u); }));
  EXPECT_EQ(first_word(*buffer), 5u);
}

TEST_F(SubmissionTest, AWaitThatTimesOutRefusesTheNextSubmissionAndIsWaitedForWhenDestroyed) {
  constexpr VkDeviceSize kBytes = VkDeviceSize(64) << 20;  // long enough for lavapipe not to finish at once
  VkResultOf<Buffer> buffer = create_storage_buffer(context(), kBytes);
  ASSERT_TRUE(buffer);
  {
    VkResultOf<Submission> submission = Submission::create(context());
    ASSERT_TRUE(submission);
    auto fill = [&](VkCommandBuffer c) { vkCmdFillBuffer(c, buffer->handle(), 0, kBytes, 3u); };
    auto timed_out = submission->submit(fill, {.timeout_ns = 0});
    if (timed_out) GTEST_SKIP() << "the device ran 64 MiB of fill before the first look at the fence";
    EXPECT_EQ(timed_out.error().code, VkErrorCode::submit_failed);
    auto refused = submission->submit(fill);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().message.find("did not finish"), std::string::npos) << refused.error().message;
  }  // destroyed: waits for the queue first, so the validation layer has nothing to say (checked at teardown)
  EXPECT_EQ(first_word(*buffer), 3u);
}

}  // namespace
}  // namespace facet::runtime
