// write_bytes_atomically(), write_atomically(), remove_stale_temporaries()
// and FileLock on real files in a temporary folder.
#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/file_lock.h"

#include <gtest/gtest.h>

#include <chrono>     // for std::chrono
#include <filesystem> // for std::filesystem
#include <fstream>    // for std::ifstream, std::ofstream
#include <iterator>   // for std::istreambuf_iterator
#include <sys/wait.h> // for waitpid
#include <thread>     // for std::this_thread::sleep_for
#include <unistd.h>   // for fork, getpid, _exit

namespace fs = std::filesystem;

namespace meshpaint::test {
namespace {

class AtomicFile : public ::testing::Test
{
protected:
  void SetUp() override
  {
    dir_ = fs::temp_directory_path() / ("atomic_file_test-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  static std::string read(const std::string& p)
  {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }

  //! Every file in the folder but `keep`.
  std::vector<std::string> others(const std::string& keep) const
  {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_))
      if (e.path().filename() != keep)
        names.push_back(e.path().filename().string());
    return names;
  }

  fs::path dir_;
};

TEST_F(AtomicFile, BytesReplaceTheFileAndLeaveNoTemporary)
{
  write_bytes_atomically(path("a.vtp"), {"old"});
  write_bytes_atomically(path("a.vtp"), {"new ", "parts"});
  EXPECT_EQ(read(path("a.vtp")), "new parts");
  EXPECT_TRUE(others("a.vtp").empty());
}

TEST_F(AtomicFile, AMissingFolderIsAnIOErrorAndWritesNothing)
{
  EXPECT_THROW(write_bytes_atomically(path("no/a.vtp"), {"x"}), IOError);
  EXPECT_FALSE(fs::exists(path("no")));
}

TEST_F(AtomicFile, AFailingWriterLeavesThePreviousFileAndNoTemporary)
{
  write_bytes_atomically(path("a.ply"), {"previous"});
  EXPECT_THROW(write_atomically(path("a.ply"),
                                [](const std::string& tmp) {
                                  std::ofstream(tmp) << "half";
                                  throw InputError("the writer gave up");
                                }),
               InputError);
  EXPECT_EQ(read(path("a.ply")), "previous");
  EXPECT_TRUE(others("a.ply").empty());
  write_atomically(path("a.ply"), [](const std::string& tmp) { std::ofstream(tmp) << "next"; });
  EXPECT_EQ(read(path("a.ply")), "next");
}

TEST_F(AtomicFile, StaleTemporariesOfEndedProcessesGoOthersStay)
{
  const pid_t child = ::fork();
  if (child == 0)
    ::_exit(0);
  ASSERT_GT(child, 0);
  ::waitpid(child, nullptr, 0); // a process that no longer runs
  const std::string ended = path(".p.tmp-" + std::to_string(child) + ".meshpaint");
  const std::string running = path(".p.tmp-" + std::to_string(::getppid()) + ".meshpaint");
  const std::string foreign = path(".notes.tmp-" + std::to_string(child) + ".txt");
  const std::string named_alike = path(".p.tmp-12x.meshpaint");
  for (const std::string& p : {ended, running, foreign, named_alike})
    std::ofstream(p) << "x";
  EXPECT_EQ(remove_stale_temporaries(path("other.vtp")), 1);
  EXPECT_FALSE(fs::exists(ended));
  EXPECT_TRUE(fs::exists(running) && fs::exists(foreign) && fs::exists(named_alike));
}

TEST_F(AtomicFile, TemporaryIsBesideTheTargetWithItsExtension)
{
  EXPECT_EQ(temporary_path(path("surface.vtp")), path(".surface.tmp-" + std::to_string(::getpid()) + ".vtp"));
}

TEST_F(AtomicFile, LockOfAMissingFileHoldsNothing)
{
  const FileLock lock(path("none.meshpaint"), nullptr);
  EXPECT_FALSE(lock.held());
}

TEST_F(AtomicFile, ASecondLockWaitsForTheFirstAndFollowsARename)
{
  const std::string p = path("p.meshpaint"), locked = path("locked"), waiting = path("waiting");
  write_bytes_atomically(p, {"v1"});
  const auto await = [](const std::string& marker) {
    while (!fs::exists(marker))
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
  };
  // Forked before the first lock is taken: a child would share its descriptor.
  const pid_t child = ::fork();
  if (child == 0) { // waits for the holder, then must hold the file the holder saved
    await(locked);
    bool waited = false;
    const FileLock second(p, [&] {
      waited = true;
      std::ofstream(waiting) << "x";
    });
    ::_exit(waited && second.held() && read(p) == "v2" ? 0 : 1);
  }
  ASSERT_GT(child, 0);
  auto lock = std::make_unique<FileLock>(p, nullptr);
  ASSERT_TRUE(lock->held());
  std::ofstream(locked) << "x";
  await(waiting); // the child is blocked on the lock
  write_bytes_atomically(p, {"v2"}); // the holder saves: a new file at p
  lock.reset();
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

} // namespace
} // namespace meshpaint::test
