// `skyig dome` as a user meets it: the MPCDI file it writes loads as calibrations, --projector
// replaces the default dome, and bad values exit 2 naming them, writing nothing.
#include "calibration/load.h"
#include "calibration/mpcdi.h"

#include "tests/node/test_support.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {

using Result = skyig::services::testing::SkyigResult;

skyig::calibration::ProjectorSource source(const std::string& path, const std::string& region) {
  skyig::calibration::ProjectorSource s;
  s.mpcdiPath = path;
  s.region = region;
  return s;
}

class DomeCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = skyig::services::testing::freshTestDirectory("skyig_dome_");
  }
  void TearDown() override { fs::remove_all(dir_); }
  Result run(const std::string& args) const { return skyig::services::testing::runSkyig("dome " + args, dir_); }
  fs::path dir_;
};

TEST_F(DomeCommand, TheDefaultDomeLoadsAsFiveProjectorsAndSaysWhatItWrote) {
  const fs::path file = dir_ / "dome.mpcdi";
  const Result r = run("--out " + file.string() + " --resolution 64x40 --warp-step 4");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("5 regions"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("overlap left / centre"), std::string::npos) << r.out;
  const auto doc = skyig::calibration::readMpcdi(file.string());
  ASSERT_EQ(doc.regions.size(), 5u);
  for (const auto& region : doc.regions) {
    const auto cal = skyig::calibration::loadProjector(source(file.string(), region.id));
    EXPECT_EQ(cal.width, 64);
    EXPECT_EQ(cal.height, 40);
    EXPECT_EQ(cal.warp.width, 17);  // every 4th of 64 pixels and the last
  }
  EXPECT_FALSE(fs::exists(dir_ / ("dome.mpcdi.tmp-" + std::to_string(::getpid()))));
}

TEST_F(DomeCommand, ProjectorFlagsReplaceTheDefaultDome) {
  const fs::path file = dir_ / "two.mpcdi";
  const Result r = run("--out " + file.string() +
                       " --profile a3 --projector west:-30,0,0:70,45:48x30 --projector east:30,0,0:70,45:48x30:0,0.2,-0.5");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto doc = skyig::calibration::readMpcdi(file.string());
  EXPECT_EQ(doc.profile, "a3");
  ASSERT_EQ(doc.regions.size(), 2u);
  EXPECT_EQ(doc.regions[0].id, "west");
  EXPECT_EQ(doc.regions[1].id, "east");
  EXPECT_NE(r.out.find("overlap west / east"), std::string::npos) << r.out;
}

TEST_F(DomeCommand, BadValuesExitTwoNamingThemAndWriteNothing) {
  const fs::path file = dir_ / "bad.mpcdi";
  for (const auto& [args, named] : std::initializer_list<std::pair<std::string, std::string>>{
           {"--radius 0", "--radius"},
           {"--contrast 0.5", "--contrast"},
           {"--warp-step 0", "--warp-step"},
           {"--profile 3d", "3d"},
           {"--eye 0,0", "--eye"},
           {"--eye 0,0,5", "eye"},
           {"--resolution 1920by1200", "1920by1200"},
           {"--projector a:0,0:60,40:64x40", "0,0"},
           {"--projector a:0,0,0:200,40:64x40", "200,40"},
           {"--projector a:0,0,0:60,40:64x40:9,0,0", "projector 'a'"},
           {"--projector a:0,0,0:60,40:64x40 --projector a:0,0,0:60,40:64x40", "taken"}}) {
    const Result r = run("--out " + file.string() + " " + args);
    EXPECT_EQ(r.exitCode, 2) << args;
    EXPECT_NE(r.err.find(named), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(fs::exists(file)) << args;
  }
}

TEST_F(DomeCommand, AnOutputThatCannotBeWrittenExitsTwo) {
  const Result r = run("--out " + dir_.string() + " --resolution 16x10");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find(dir_.string()), std::string::npos) << r.err;
  const Result missing = run("--out " + (dir_ / "no" / "such.mpcdi").string() + " --resolution 16x10");
  EXPECT_EQ(missing.exitCode, 2);
}

}  // namespace
