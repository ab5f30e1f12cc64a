// The one atomic file writer: outputs appear whole or not at all, and no
// temporary is left behind, whatever fails.
#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "facet/support/atomic_file.h"
#include "facet/support/text.h"

namespace facet::support {
namespace {
namespace fs = std::filesystem;

class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("facet_atomic_file_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    return names;
  }
  static std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
  fs::path dir_;
};

TEST_F(AtomicFileTest, WritesTheWholeContentAndLeavesOnlyTheTarget) {
  std::string target = (dir_ / "out.facetpkg").string();
  ASSERT_TRUE(write_file_atomically(target, "first"));
  ASSERT_TRUE(write_file_atomically(target, "second, longer"));
  EXPECT_EQ(read(target), "second, longer");
  EXPECT_THAT(files(), ::testing::ElementsAre("out.facetpkg"));
}

TEST_F(AtomicFileTest, TheTemporaryIsBesideTheTargetNamedByProcessAndKeepsTheExtension) {
  std::string target = (dir_ / "frame.png").string();
  std::string seen;
  ASSERT_TRUE(replace_file_atomically(target, [&](const std::string& temporary) -> Result<void, std::string> {
    seen = temporary;
    std::ofstream(temporary) << "pixels";
    return {};
  }));
  EXPECT_THAT(seen, ::testing::StartsWith(target + ".tmp." + std::to_string(::getpid()) + "."));
  EXPECT_THAT(seen, ::testing::EndsWith(".png"));
  EXPECT_EQ(read(target), "pixels");
}

TEST_F(AtomicFileTest, AFailingWriterKeepsTheOldFileAndRemovesItsTemporary) {
  std::string target = (dir_ / "report.json").string();
  ASSERT_TRUE(write_file_atomically(target, "old"));
  Result<void, std::string> written = replace_file_atomically(target, [](const std::string& temporary) {
    std::ofstream(temporary) << "half";
    return Result<void, std::string>(unexpected(std::string("disk full")));
  });
  ASSERT_FALSE(written);
  EXPECT_EQ(written.error(), "disk full");
  EXPECT_EQ(read(target), "old");
  EXPECT_THAT(files(), ::testing::ElementsAre("report.json"));
}

TEST_F(AtomicFileTest, AFolderInTheTargetsPlaceIsAnErrorAndStaysAsItWas) {
  fs::create_directories(dir_ / "taken" / "inside");
  Result<void, std::string> written = write_file_atomically((dir_ / "taken").string(), "bytes");
  ASSERT_FALSE(written);
  EXPECT_FALSE(written.error().empty());
  EXPECT_TRUE(fs::is_directory(dir_ / "taken" / "inside"));
  EXPECT_THAT(files(), ::testing::ElementsAre("taken"));
}

// Renaming over a device node would replace it with a file: as root,
// `facetc X.shader -o /dev/null` replaced the system's /dev/null.
TEST_F(AtomicFileTest, ACharacterDeviceIsWrittenInPlaceAndStaysADevice) {
  std::string device = (dir_ / "null").string();
  if (::mknod(device.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0) GTEST_SKIP() << "mknod needs root";
  ASSERT_TRUE(write_file_atomically(device, "a package"));
  struct stat st {};
  ASSERT_EQ(::stat(device.c_str(), &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  EXPECT_THAT(files(), ::testing::ElementsAre("null"));
}

TEST_F(AtomicFileTest, AFifoThatAProcessReadsReceivesTheBytes) {
  std::string fifo = (dir_ / "pipe").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0666), 0);
  std::string received;
  std::thread reader([&] { received = read(fifo); });
  // Written once the reader has the FIFO open (until then it is refused as unread).
  Result<void, std::string> written = unexpected(std::string("not tried"));
  for (int i = 0; i < 2000 && !written; ++i) {
    written = write_file_atomically(fifo, "streamed bytes");
    if (!written) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (!written) ::close(::open(fifo.c_str(), O_WRONLY | O_NONBLOCK));  // lets the reader's open return
  reader.join();
  ASSERT_TRUE(written) << written.error();
  EXPECT_EQ(received, "streamed bytes");
  struct stat st {};
  ASSERT_EQ(::stat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
}

TEST_F(AtomicFileTest, AFifoNobodyReadsIsAnErrorNotAHang) {
  std::string fifo = (dir_ / "pipe").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0666), 0);
  Result<void, std::string> written = write_file_atomically(fifo, "bytes");
  ASSERT_FALSE(written);
  EXPECT_THAT(written.error(), ::testing::HasSubstr("FIFO that no process is reading"));
  struct stat st {};
  ASSERT_EQ(::stat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  EXPECT_THAT(files(), ::testing::ElementsAre("pipe"));
}

// A cache entry's place held by a FIFO is repaired: facet's own files replace what stands there.
TEST_F(AtomicFileTest, AFifoInTheWayOfFacetsOwnFileIsReplaced) {
  std::string fifo = (dir_ / "entry").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0666), 0);
  ASSERT_TRUE(write_file_atomically(fifo, "entry bytes", SpecialTarget::replace));
  EXPECT_TRUE(fs::is_regular_file(fifo));
  EXPECT_EQ(read(fifo), "entry bytes");
}

TEST_F(AtomicFileTest, AMissingFolderIsAnErrorNamingWhy) {
  Result<void, std::string> written = write_file_atomically((dir_ / "no" / "such" / "x.bin").string(), "bytes");
  ASSERT_FALSE(written);
  EXPECT_THAT(lower(written.error()), ::testing::HasSubstr("no such file"));
}

// mkstemp would make the output 0600; the writer keeps what a plain
// ofstream gives: 0666 less the umask.
TEST_F(AtomicFileTest, TheOutputHasTheModeOfAPlainlyCreatedFile) {
  const mode_t old_mask = ::umask(022);
  std::string target = (dir_ / "mode.bin").string();
  ASSERT_TRUE(write_file_atomically(target, "x"));
  ::umask(old_mask);
  struct stat info {};
  ASSERT_EQ(::stat(target.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0644u);
}

TEST_F(AtomicFileTest, ConcurrentWritersOfOneTargetLeaveOneWholeContent) {
  std::string target = (dir_ / "shared.bin").string();
  std::set<std::string> contents;
  for (int i = 0; i < 8; ++i) contents.insert(std::string(4096 + i * 512, char('a' + i)));
  std::vector<std::thread> writers;
  for (const std::string& content : contents) {
    writers.emplace_back([&target, &content] {
      for (int round = 0; round < 20; ++round) EXPECT_TRUE(write_file_atomically(target, content));
    });
  }
  for (std::thread& t : writers) t.join();
  EXPECT_EQ(contents.count(read(target)), 1u) << "the target holds one writer's whole content";
  EXPECT_THAT(files(), ::testing::ElementsAre("shared.bin"));
}

}  // namespace
}  // namespace facet::support
