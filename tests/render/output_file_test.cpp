// Outputs never replace what they are pointed at: a regular file is replaced atomically; a FIFO,
// /dev/null and a link's target are written in place and stay what they were; a full disk is an
// error naming the path that leaves the previous file as it was, with no temporary file.
#include "render/output_file.h"

#include <gtest/gtest.h>

#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

namespace skyig::render {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class OutputFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("skyig_output_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // No PATH.tmp-PID left beside the outputs.
  void expectNoTemporaryIn(const fs::path& dir) const {
    for (const auto& entry : fs::directory_iterator(dir))
      EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
  }

  fs::path dir_;
};

TEST_F(OutputFile, ARegularFileIsReplacedWhole) {
  const fs::path p = dir_ / "stats.json";
  std::ofstream(p) << "previous, longer than what replaces it";
  struct stat before {};
  ASSERT_EQ(::stat(p.c_str(), &before), 0);
  writeOutputFile(p.string(), std::string("new"));
  EXPECT_EQ(slurp(p), "new");
  struct stat after {};
  ASSERT_EQ(::stat(p.c_str(), &after), 0);
  EXPECT_NE(before.st_ino, after.st_ino);  // a new file renamed over the old: never half written
  expectNoTemporaryIn(dir_);
}

TEST_F(OutputFile, AFifoIsWrittenInPlaceAndStaysAFifo) {
  const fs::path fifo = dir_ / "frames";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = slurp(fifo); });
  writeOutputFile(fifo.string(), std::string("frame bytes"));
  reader.join();
  EXPECT_EQ(received, "frame bytes");
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));
  expectNoTemporaryIn(dir_);
}

TEST_F(OutputFile, DevNullIsWrittenAndStaysACharacterDevice) {
  struct stat before {};
  ASSERT_EQ(::stat("/dev/null", &before), 0);
  ASSERT_TRUE(S_ISCHR(before.st_mode));
  checkOutputPath("/dev/null");
  writeOutputFile("/dev/null", std::string("discarded"));
  struct stat after {};
  ASSERT_EQ(::stat("/dev/null", &after), 0);
  EXPECT_TRUE(S_ISCHR(after.st_mode));
  EXPECT_EQ(before.st_ino, after.st_ino);
  EXPECT_EQ(before.st_rdev, after.st_rdev);
}

TEST_F(OutputFile, ALinkIsFollowedToItsTargetAndKept) {
  fs::create_directories(dir_ / "real");
  const fs::path target = dir_ / "real" / "sky.png";
  std::ofstream(target) << "old";
  const fs::path link = dir_ / "latest.png";
  fs::create_symlink("real/sky.png", link);  // relative, as people make them
  writeOutputFile(link.string(), std::string("new image"));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  EXPECT_EQ(fs::read_symlink(link), fs::path("real/sky.png"));
  EXPECT_EQ(slurp(target), "new image");
  // A link whose target does not exist yet: the target is made, the link stays.
  const fs::path dangling = dir_ / "next.png";
  fs::create_symlink(dir_ / "real" / "next.png", dangling);
  writeOutputFile(dangling.string(), std::string("first"));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dangling)));
  EXPECT_EQ(slurp(dir_ / "real" / "next.png"), "first");
  expectNoTemporaryIn(dir_);
  expectNoTemporaryIn(dir_ / "real");
}

TEST_F(OutputFile, DirectoriesAndMissingDirectoriesAreRefused) {
  EXPECT_THROW(checkOutputPath(dir_.string()), OutputPathError);
  EXPECT_THROW(writeOutputFile(dir_.string(), std::string("x")), OutputPathError);
  try {
    writeOutputFile((dir_ / "missing" / "x.png").string(), std::string("x"));
    FAIL() << "wrote into a missing directory";
  } catch (const OutputPathError& e) {
    EXPECT_NE(std::string(e.what()).find((dir_ / "missing").string()), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_directory(dir_));
}

TEST_F(OutputFile, TwoOutputsNamingOneFileAreRefused) {
  const std::string a = (dir_ / "x.png").string();
  EXPECT_THROW(checkDistinctOutputs({{"--png", a}, {"--exr", a}}), OutputPathError);
  // The same file through a link or another spelling is the same file.
  fs::create_symlink(a, dir_ / "y.png");
  EXPECT_THROW(checkDistinctOutputs({{"--png", a}, {"--exr", (dir_ / "y.png").string()}}), OutputPathError);
  EXPECT_THROW(checkDistinctOutputs({{"--png", a}, {"--exr", (dir_ / "." / "x.png").string()}}), OutputPathError);
  EXPECT_THROW(checkDistinctOutputs({{"--png", "-"}, {"--exr", "-"}}), OutputPathError);
  EXPECT_NO_THROW(checkDistinctOutputs(
      {{"--png", a}, {"--exr", (dir_ / "x.exr").string()}, {"--stats-json", ""}, {"--record", ""}}));
}

// A full file system (a 64 KiB tmpfs mounted in the test's directory; root only): a clear
// error naming the path, the previous file intact, the temporary removed.
TEST_F(OutputFile, AFullDiskIsAnErrorAndKeepsThePreviousFile) {
  const fs::path mountPoint = dir_ / "small";
  fs::create_directories(mountPoint);
  if (::geteuid() != 0 || ::mount("skyig-test", mountPoint.c_str(), "tmpfs", 0, "size=64k") != 0)
    GTEST_SKIP() << "cannot mount a small tmpfs here (not root, or no mount permission)";
  struct Unmount {
    fs::path at;
    ~Unmount() { ::umount2(at.c_str(), MNT_DETACH); }
  } unmount{mountPoint};
  const fs::path p = mountPoint / "sky.png";
  const std::string previous(16 * 1024, 'p');
  writeOutputFile(p.string(), previous);
  const std::string tooLarge(200 * 1024, 'n');
  try {
    writeOutputFile(p.string(), tooLarge);
    FAIL() << "wrote 200 KiB into a 64 KiB file system";
  } catch (const OutputWriteError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(p.string()), std::string::npos) << what;
    EXPECT_NE(what.find("No space left on device"), std::string::npos) << what;
  }
  EXPECT_EQ(slurp(p), previous);
  expectNoTemporaryIn(mountPoint);
}

}  // namespace
}  // namespace skyig::render
