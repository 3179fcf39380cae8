// skyig's data directory (ephemeris/data_files.h): $SKYIG_DATA_DIR when set, else beside the
// running executable (<dir>/../share/skyig); a missing file names the path tried and the variable.
#include "ephemeris/data_files.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

namespace fs = std::filesystem;
using namespace skyig::ephemeris;

namespace {

// Sets (or with null unsets) SKYIG_DATA_DIR for one scope; the test programs' own value
// (tests/staged_data_dir.cpp) comes back after it.
class DataDirVariable {
 public:
  explicit DataDirVariable(const char* value) {
    if (const char* old = std::getenv("SKYIG_DATA_DIR")) old_ = old;
    if (value) ::setenv("SKYIG_DATA_DIR", value, 1);
    else ::unsetenv("SKYIG_DATA_DIR");
  }
  ~DataDirVariable() {
    if (old_) ::setenv("SKYIG_DATA_DIR", old_->c_str(), 1);
    else ::unsetenv("SKYIG_DATA_DIR");
  }
  DataDirVariable(const DataDirVariable&) = delete;
  DataDirVariable& operator=(const DataDirVariable&) = delete;

 private:
  std::optional<std::string> old_;
};

}  // namespace

TEST(DataDirectory, TheVariableWinsOverTheExecutable) {
  EXPECT_EQ(dataDirectory("/srv/skyig-data", "/usr/bin/skyig"), fs::path("/srv/skyig-data"));
}

TEST(DataDirectory, ElseShareBesideTheExecutablesDirectory) {
  EXPECT_EQ(dataDirectory(nullptr, "/usr/bin/skyig"), fs::path("/usr/share/skyig"));
  EXPECT_EQ(dataDirectory("", "/opt/skyig/bin/skyig"), fs::path("/opt/skyig/share/skyig"));  // empty = unset
  EXPECT_EQ(dataDirectory(nullptr, "/work/build/bin/skyig"), fs::path("/work/build/share/skyig"));
  EXPECT_TRUE(dataDirectory(nullptr, "").empty());
}

TEST(DataDirectory, ThisProcessWithoutTheVariableLooksBesideItsExecutable) {
  const fs::path exe = fs::read_symlink("/proc/self/exe");
  DataDirVariable unset(nullptr);
  EXPECT_EQ(dataDirectory(), (exe.parent_path() / ".." / "share" / "skyig").lexically_normal());
  EXPECT_EQ(dataFilePath("bsc5.csv"), (dataDirectory() / "bsc5.csv").string());
}

TEST(DataDirectory, ThisProcessWithTheVariable) {
  const fs::path dir = fs::temp_directory_path() / ("skyig_data_dir_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "bsc5.csv") << "# a stand-in\n";
  {
    DataDirVariable set(dir.c_str());
    EXPECT_EQ(dataDirectory(), dir);
    EXPECT_EQ(requireDataFile("bsc5.csv"), (dir / "bsc5.csv").string());
  }
  fs::remove_all(dir);
}

TEST(DataDirectory, AMissingFileNamesThePathAndTheVariable) {
  for (const char* value : {"/nonexistent-skyig-data", static_cast<const char*>(nullptr)}) {
    DataDirVariable set(value);
    const std::string tried = dataFilePath("moon.png");
    try {
      requireDataFile("moon.png");
      FAIL() << "found " << tried;
    } catch (const DataFileError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(tried), std::string::npos) << what;
      EXPECT_NE(what.find("SKYIG_DATA_DIR"), std::string::npos) << what;
    }
  }
}

// The staged copy the test programs read (cmake/DataFiles.cmake) holds every file.
TEST(DataDirectory, TheBuildTreeStagesEveryFile) {
  for (const char* name : {"bsc5.csv", "moon.png", "milkyway.png"})
    EXPECT_TRUE(fs::is_regular_file(requireDataFile(name))) << name;
}
