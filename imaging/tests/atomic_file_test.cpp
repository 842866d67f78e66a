// The atomic file writer: concurrent writers of one target (threads and
// processes) never let a reader see a torn or missing file, and a failed
// write leaves the old target and no temporary behind.
#include "imaging/atomic_file.h"

#include "imaging/tests/scratch_folder_test.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace imaging {
namespace {

namespace fs = std::filesystem;

constexpr int kWritesPerWriter = 200;

using AtomicFileTest = testing::ScratchFolderTest;

std::optional<std::string> readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Reads `target` over and over on its own thread until stop(), counting the
// reads that found no file or something other than one of the two contents
// whole. The two contents differ in length and in every byte, so any mix of
// them, or a prefix of either, is caught.
class Reader {
 public:
  Reader(fs::path target, std::string a, std::string b)
      : target_(std::move(target)), a_(std::move(a)), b_(std::move(b)), thread_([this] { run(); }) {}
  ~Reader() { stop(); }

  void stop() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  int reads() const { return reads_; }
  int missing() const { return missing_; }
  int torn() const { return torn_; }

 private:
  void run() {
    while (!stop_) {
      const std::optional<std::string> content = readFile(target_);
      ++reads_;
      if (!content) ++missing_;
      else if (*content != a_ && *content != b_) ++torn_;
    }
  }

  fs::path target_;
  std::string a_, b_;
  std::atomic<bool> stop_{false};
  std::atomic<int> reads_{0}, missing_{0}, torn_{0};
  std::thread thread_;
};

// Writes `content` over `target` kWritesPerWriter times; returns how many
// of the writes threw.
int writeRepeatedly(const fs::path& target, const std::string& content) {
  int failures = 0;
  for (int i = 0; i < kWritesPerWriter; ++i) {
    try {
      writeFileAtomically(target, content);
    } catch (const std::exception&) {
      ++failures;
    }
  }
  return failures;
}

const std::string kContentA(64 * 1024, 'a');
const std::string kContentB(96 * 1024, 'b');

TEST_F(AtomicFileTest, TwoThreadsWritingOneTargetNeverTearIt) {
  const fs::path target = dir_ / "results.json";
  writeFileAtomically(target, kContentA);
  Reader reader(target, kContentA, kContentB);
  std::atomic<int> failures{0};
  std::thread other([&] { failures += writeRepeatedly(target, kContentB); });
  failures += writeRepeatedly(target, kContentA);
  other.join();
  reader.stop();

  EXPECT_EQ(failures, 0);
  EXPECT_GT(reader.reads(), 0);
  EXPECT_EQ(reader.missing(), 0);
  EXPECT_EQ(reader.torn(), 0);
  EXPECT_EQ(namesInFolder(), std::vector<std::string>{"results.json"});  // no temporary left
}

TEST_F(AtomicFileTest, TwoProcessesWritingOneTargetNeverTearIt) {
  const fs::path target = dir_ / "vulkan-pipelines.bin";
  writeFileAtomically(target, kContentA);
  // Forked before any thread of this test starts, so the child is a copy of
  // one thread; the counter in the temporary name is copied too, and only
  // the pid keeps the two processes' temporaries apart.
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) ::_exit(writeRepeatedly(target, kContentB) == 0 ? 0 : 1);

  int failures = 0;
  {
    Reader reader(target, kContentA, kContentB);
    failures = writeRepeatedly(target, kContentA);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    reader.stop();
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "the child's writes threw";
    EXPECT_GT(reader.reads(), 0);
    EXPECT_EQ(reader.missing(), 0);
    EXPECT_EQ(reader.torn(), 0);
  }
  EXPECT_EQ(failures, 0);
  EXPECT_EQ(namesInFolder(), std::vector<std::string>{"vulkan-pipelines.bin"});
}

TEST_F(AtomicFileTest, AFailingWriterLeavesTheOldTargetAndNoTemporary) {
  const fs::path target = dir_ / "image.exr";
  writeFileAtomically(target, "old");
  struct WriterFailure {};
  fs::path used;
  EXPECT_THROW(writeThroughTemporary(target,
                                     [&](const fs::path& temporary) {
                                       used = temporary;
                                       std::ofstream(temporary, std::ios::binary) << "half of the new";
                                       throw WriterFailure{};  // the writer's own exception goes on
                                     }),
               WriterFailure);
  EXPECT_EQ(used.parent_path(), target.parent_path());
  EXPECT_EQ(readFile(target), "old");
  EXPECT_EQ(namesInFolder(), std::vector<std::string>{"image.exr"});
}

TEST_F(AtomicFileTest, AFailedRenameThrowsAndLeavesNoTemporary) {
  // A folder that is not empty cannot be replaced by a file.
  const fs::path target = dir_ / "summary.json";
  fs::create_directories(target / "inside");
  try {
    writeFileAtomically(target, "new");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write " + target.string()), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_directory(target / "inside"));
  EXPECT_EQ(namesInFolder(), std::vector<std::string>{"summary.json"});
}

TEST_F(AtomicFileTest, AWriterThatWritesNothingFailsAndLeavesTheTarget) {
  const fs::path target = dir_ / "bake.json";
  writeFileAtomically(target, "old");
  EXPECT_THROW(writeThroughTemporary(target, [](const fs::path&) {}), std::runtime_error);
  EXPECT_EQ(readFile(target), "old");
  EXPECT_EQ(namesInFolder(), std::vector<std::string>{"bake.json"});
}

TEST_F(AtomicFileTest, AFolderThatCannotBeMadeThrows) {
  writeFileAtomically(dir_ / "file", "x");
  EXPECT_THROW(writeFileAtomically(dir_ / "file" / "below" / "a.txt", "y"), std::runtime_error);
  EXPECT_EQ(namesInFolder(), std::vector<std::string>{"file"});
}

TEST_F(AtomicFileTest, WritesEveryByteAndMakesTheFolder) {
  const std::string bytes("binary\0with\0zeros\n", 18);
  const fs::path target = dir_ / "a" / "b" / "cache.bake";
  writeFileAtomically(target, bytes);
  EXPECT_EQ(readFile(target), bytes);
  writeFileAtomically(target, "shorter");
  EXPECT_EQ(readFile(target), "shorter");  // replaced, not overwritten in place
}

TEST_F(AtomicFileTest, TheTemporaryIsHiddenBesideTheTargetKeepsTheExtensionAndIsNewEachCall) {
  const fs::path target = dir_ / "evidence" / "diff.png";
  const fs::path first = temporaryPathFor(target);
  const fs::path second = temporaryPathFor(target);
  EXPECT_EQ(first.parent_path(), target.parent_path());
  EXPECT_EQ(first.extension(), ".png");  // OpenImageIO picks the format from it
  const std::string name = first.filename().string();
  EXPECT_EQ(name.rfind(".diff." + std::to_string(::getpid()) + ".", 0), 0u) << name;
  EXPECT_NE(name.find(".partial.png"), std::string::npos) << name;
  EXPECT_NE(first, second);
}

}  // namespace
}  // namespace imaging
