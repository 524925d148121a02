#include "testbed/io/output_files.h"

#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "testbed/core/error.h"
#include "tests/cli_helpers.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;
using namespace testbed::test;

TEST(OutputFiles, AppearOnlyOnCommitAndAnAbandonedSetRemovesTheFolderItMade) {
  const TempDir tmp("testbed-output-files");
  const fs::path dir = tmp.path() / "a" / "b";
  {
    OutputFiles files(dir);
    EXPECT_TRUE(fs::is_directory(dir)) << "the folder is checked by making it, before any rendering";
    files.writeText("a.json", "{}\n");
    EXPECT_FALSE(fs::exists(dir / "a.json"));
  }
  EXPECT_FALSE(fs::exists(tmp.path() / "a")) << "both folders it made are gone";
  {
    OutputFiles files(dir);
    files.writeText("b.json", "{}\n");
    files.commit();
  }
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{"b.json"});
}

TEST(OutputFiles, ReplacesRegularFilesAndLeavesTheUsersOtherFilesAlone) {
  const TempDir tmp("testbed-output-files");
  writeFile(tmp.path() / "sm.json", "old\n");
  writeFile(tmp.path() / "sm.json.previous", "the user's own\n");
  writeFile(tmp.path() / "sm.json.partial", "the user's too\n");
  OutputFiles files(tmp.path());
  files.writeText("sm.json", "new\n");
  files.commit();
  EXPECT_EQ(readFile(tmp.path() / "sm.json"), "new\n");
  EXPECT_EQ(readFile(tmp.path() / "sm.json.previous"), "the user's own\n");
  EXPECT_EQ(readFile(tmp.path() / "sm.json.partial"), "the user's too\n");
  EXPECT_EQ(filesIn(tmp.path()), (std::vector<std::string>{"sm.json", "sm.json.partial", "sm.json.previous"}));
}

TEST(OutputFiles, NeverReplacesOrWritesThroughALinkAFifoOrAFolder) {
  const TempDir tmp("testbed-output-files");
  writeFile(tmp.path() / "victim", "precious\n");
  fs::create_symlink(tmp.path() / "victim", tmp.path() / "link.json");
  ASSERT_EQ(::mkfifo((tmp.path() / "fifo.json").c_str(), 0600), 0);
  fs::create_directory(tmp.path() / "folder.json");
  for (const char* name : {"link.json", "fifo.json", "folder.json"}) {
    SCOPED_TRACE(name);
    OutputFiles files(tmp.path());
    EXPECT_THROW(files.claim(name), InputError);
    EXPECT_THROW(files.writeText(name, "new\n"), InputError);
  }
  EXPECT_EQ(readFile(tmp.path() / "victim"), "precious\n");
  EXPECT_TRUE(fs::is_symlink(tmp.path() / "link.json"));
  EXPECT_TRUE(fs::is_fifo(tmp.path() / "fifo.json"));
  // A name taken after the writes is refused at commit, with nothing of the set placed.
  writeFile(tmp.path() / "a.json", "old a\n");
  {
    OutputFiles files(tmp.path());
    files.writeText("a.json", "new a\n");
    files.writeText("b.json", "new b\n");
    fs::create_symlink(tmp.path() / "victim", tmp.path() / "b.json");
    EXPECT_THROW(files.commit(), InputError);
  }
  EXPECT_EQ(readFile(tmp.path() / "a.json"), "old a\n");
  EXPECT_EQ(readFile(tmp.path() / "victim"), "precious\n");
  EXPECT_TRUE(fs::is_symlink(tmp.path() / "b.json"));
}

TEST(OutputFiles, BadFoldersAreInputErrorsBeforeAnythingIsWritten) {
  const TempDir tmp("testbed-output-files");
  writeFile(tmp.path() / "file", "x\n");
  for (const fs::path& bad : {fs::path(""), tmp.path() / "file", tmp.path() / "file" / "under",
                              tmp.path() / std::string(300, 'n'), fs::path("/proc/testbed-no-such")}) {
    SCOPED_TRACE(bad.string());
    EXPECT_THROW(OutputFiles files(bad), InputError);
  }
  EXPECT_EQ(filesIn(tmp.path()), std::vector<std::string>{"file"});
  OutputFiles files(tmp.path());
  EXPECT_THROW(files.claim(std::string(300, 'f')), InputError);
  EXPECT_THROW(files.claim("../escape"), InputError);
}

TEST(OutputFiles, StagingIsAPrivateHiddenFolderRemovedAfterwards) {
  const TempDir tmp("testbed-output-files");
  {
    OutputFiles files(tmp.path());
    files.writeText("x.json", "{}\n");
    const auto names = filesIn(tmp.path());
    ASSERT_EQ(names.size(), 1u);
    EXPECT_EQ(names[0].rfind(".testbed-staging-", 0), 0u) << names[0];
    struct stat info {};
    ASSERT_EQ(::stat((tmp.path() / names[0]).c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 0777, 0700u);
  }
  EXPECT_TRUE(filesIn(tmp.path()).empty());
}


// Shards started together (the Slurm layout OUT/shards/K-of-N) create the same missing
// parents at once: whoever loses the race on a parent finds it made, which is success.
TEST(OutputFiles, SiblingsCreatedTogetherUnderAFreshParentAllSucceed) {
  const TempDir tmp("testbed-output-files");
  constexpr int kRounds = 20, kThreads = 8;
  for (int round = 0; round < kRounds; ++round) {
    const fs::path parent = tmp.path() / ("run-" + std::to_string(round)) / "shards";
    std::atomic<int> ready{0}, failures{0};
    std::vector<std::thread> threads;
    for (int k = 0; k < kThreads; ++k)
      threads.emplace_back([&, k] {
        ++ready;
        while (ready.load() < kThreads) std::this_thread::yield();  // start together
        try {
          OutputFiles files(parent / (std::to_string(k + 1) + "-of-" + std::to_string(kThreads)));
          files.writeText("records.json", "[]\n");
          files.commit();
        } catch (const std::exception&) {
          ++failures;
        }
      });
    for (auto& t : threads) t.join();
    ASSERT_EQ(failures.load(), 0) << "round " << round;
    EXPECT_EQ(filesIn(parent).size(), std::size_t(kThreads));
  }
}

}  // namespace
}  // namespace testbed
