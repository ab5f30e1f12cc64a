// CrashIsolation: work in a child process, whose crash is an answer.
#include "crash_isolation.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <thread>
#include <vector>

namespace facet::backend {
namespace {

std::string reversed(std::string_view request) { return std::string(request.rbegin(), request.rend()); }

std::string own_process_id(std::string_view) { return std::to_string(getpid()); }

std::string crashes(std::string_view) {
  std::raise(SIGSEGV);
  return "unreachable";
}

std::string aborts(std::string_view) { std::abort(); }

std::string exits(std::string_view) { _exit(7); }

// Deep recursion needs the large stack the child runs its handler on.
size_t depth(size_t n) {
  volatile char frame[512];
  frame[0] = char(n);
  return n == 0 ? size_t(frame[0]) : depth(n - 1) + 1;
}

std::string recurses(std::string_view) { return std::to_string(depth(100000)); }

TEST(CrashIsolationTest, AChildAnswersWithWhatItsHandlerReturns) {
  CrashIsolation isolation;
  ChildAnswer answer = isolation.run(reversed, "abc", 10);
  ASSERT_EQ(answer.kind, ChildAnswer::Kind::answered);
  EXPECT_EQ(answer.bytes, "cba");
}

TEST(CrashIsolationTest, TheHandlerRunsInAnotherProcess) {
  CrashIsolation isolation;
  ChildAnswer answer = isolation.run(own_process_id, "", 10);
  ASSERT_EQ(answer.kind, ChildAnswer::Kind::answered);
  EXPECT_NE(answer.bytes, std::to_string(getpid()));
}

TEST(CrashIsolationTest, AWorkerServesOneRequestAfterAnotherAndOneThatDiedIsReplaced) {
  CrashIsolation isolation;
  ChildAnswer first = isolation.run(own_process_id, "", 10);
  ChildAnswer second = isolation.run(own_process_id, "", 10);
  ASSERT_EQ(first.kind, ChildAnswer::Kind::answered);
  ASSERT_EQ(second.kind, ChildAnswer::Kind::answered);
  EXPECT_EQ(first.bytes, second.bytes);
  EXPECT_EQ(isolation.run(crashes, "", 10).kind, ChildAnswer::Kind::died);
  ChildAnswer after = isolation.run(own_process_id, "", 10);
  ASSERT_EQ(after.kind, ChildAnswer::Kind::answered);
  EXPECT_NE(after.bytes, first.bytes);
}

TEST(CrashIsolationTest, AChildThatCrashesAbortsOrExitsDiesAndTheNextRequestIsAnswered) {
  CrashIsolation isolation;
  for (CrashIsolation::Handler handler : {crashes, aborts, exits}) {
    EXPECT_EQ(isolation.run(handler, "x", 10).kind, ChildAnswer::Kind::died);
    ChildAnswer after = isolation.run(reversed, "xy", 10);
    ASSERT_EQ(after.kind, ChildAnswer::Kind::answered);
    EXPECT_EQ(after.bytes, "yx");
  }
}

TEST(CrashIsolationTest, RequestsAndAnswersOfMegabytesCrossWhole) {
  CrashIsolation isolation;
  std::string request(8u << 20, '\0');
  for (size_t i = 0; i < request.size(); ++i) request[i] = char(i * 7 + i / 251);
  ChildAnswer answer = isolation.run(reversed, request, 30);
  ASSERT_EQ(answer.kind, ChildAnswer::Kind::answered);
  EXPECT_EQ(answer.bytes, reversed(request));
}

TEST(CrashIsolationTest, TheHandlerHasTheWorkersLargeStack) {
  CrashIsolation isolation;
  ChildAnswer answer = isolation.run(recurses, "", 30);
  ASSERT_EQ(answer.kind, ChildAnswer::Kind::answered);
  EXPECT_EQ(answer.bytes, "100000");
}

TEST(CrashIsolationTest, ThreadsShareOneIsolationAndEachGetsItsOwnAnswer) {
  CrashIsolation isolation;
  std::vector<std::string> answers(8);
  std::vector<std::thread> threads;
  for (size_t t = 0; t < answers.size(); ++t) {
    threads.emplace_back([&, t] {
      for (int i = 0; i < 10; ++i) {
        std::string request = std::to_string(t) + ":" + std::to_string(i);
        ChildAnswer answer = isolation.run(i % 3 == 0 ? crashes : reversed, request, 10);
        bool right = i % 3 == 0 ? answer.kind == ChildAnswer::Kind::died
                                : answer.kind == ChildAnswer::Kind::answered && answer.bytes == reversed(request);
        if (!right) answers[t] += "wrong answer to " + request + "; ";
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (const std::string& wrong : answers) EXPECT_EQ(wrong, "");
}

TEST(CrashIsolationTest, TheWireReadsBackWhatWasWrittenAndRefusesTruncatedBytes) {
  WireWriter w;
  w.byte(9);
  w.u32(123456);
  w.text("text");
  w.words({1, 2, 0xffffffffu});
  std::string bytes = w.take();
  WireReader r(bytes);
  EXPECT_EQ(r.byte(), 9);
  EXPECT_EQ(r.u32(), 123456u);
  EXPECT_EQ(r.text(), "text");
  EXPECT_EQ(r.words(), (std::vector<uint32_t>{1, 2, 0xffffffffu}));
  EXPECT_TRUE(r.at_end());
  for (size_t cut = 0; cut < bytes.size(); ++cut) {
    WireReader short_read(std::string_view(bytes).substr(0, cut));
    short_read.byte();
    short_read.u32();
    short_read.text();
    short_read.words();
    EXPECT_FALSE(short_read.ok()) << cut;
  }
  WireWriter huge;
  huge.u32(0xfffffff0u);  // a text or word count the bytes cannot hold
  std::string claim = huge.take();
  EXPECT_EQ(WireReader(claim).text(), "");
  WireReader words(claim);
  EXPECT_TRUE(words.words().empty());
  EXPECT_FALSE(words.ok());
}

}  // namespace
}  // namespace facet::backend
