// `skyig render --goggle`: a goggle channel's files, written by the real executable. The EXR
// holds the NVIS radiance with its unit and the goggle's frustum in its header; the PNG is the
// goggle's screen, black outside its circle.
#include "render/image_io.h"

#include <gtest/gtest.h>
#include <png.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;

namespace {

int runSkyig(const std::string& args, const fs::path& log) {
  const std::string command = "XDG_CACHE_HOME=" + std::string(SKYIG_BINARY_DIR) + "/atmosphere-test-cache " +
                              std::string(SKYIG_EXECUTABLE) + " " + args + " >" + log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

fs::path lookConfig() { return fs::path(SKYIG_SOURCE_DIR) / "tests" / "data" / "golden" / "look.toml"; }

}  // namespace

TEST(GoggleRender, ExrCarriesTheNvisRadianceAndItsUnit) {
  const fs::path dir = fs::temp_directory_path() / ("skyig_goggle_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string args = "render --config " + lookConfig().string() +
                           " --utc 2026-12-25T17:40:00Z --yaw 60 --pitch 2 --size 64x48 --goggle B --phosphor P45";
  ASSERT_EQ(runSkyig(args + " --exr " + (dir / "nvg.exr").string() + " --png " + (dir / "nvg.png").string(), dir / "log"), 0);
  const skyig::render::ExrFile exr = skyig::render::readExr((dir / "nvg.exr").string());
  auto text = [&](const char* key) {
    const auto it = exr.attributes.find(key);
    return it == exr.attributes.end() ? std::string() : std::get<std::string>(it->second);
  };
  auto number = [&](const char* key) {
    const auto it = exr.attributes.find(key);
    return it == exr.attributes.end() ? -1.0 : std::get<double>(it->second);
  };
  EXPECT_EQ(text("skyig:units").rfind("NVIS radiance, class B: W m^-2 sr^-1", 0), 0u) << text("skyig:units");
  EXPECT_EQ(text("skyig:nvis_class"), "B");
  EXPECT_EQ(text("skyig:goggle_phosphor"), "P45");
  EXPECT_DOUBLE_EQ(number("skyig:goggle_field_of_view_deg"), 40.0);
  EXPECT_DOUBLE_EQ(number("skyig:frustum_up_deg"), 20.0);  // the goggle's 40 deg field fills the height
  EXPECT_DOUBLE_EQ(number("skyig:frustum_down_deg"), 20.0);
  // The NVIS radiance, the same in R, G and B; the rising full moon's sky is some 1e-6 to 1e-3
  // W m^-2 sr^-1 (its disc far more), never cd/m^2 of a daylight sky.
  const float* centre = exr.image.pixel(32, 10);
  EXPECT_EQ(centre[0], centre[1]);
  EXPECT_EQ(centre[2], centre[1]);
  EXPECT_GT(centre[1], 1e-7f);
  EXPECT_LT(centre[1], 1e-2f);
  fs::remove_all(dir);
}

// A goggle class the standard does not have, or a phosphor skyig does not know, is refused
// before anything renders (exit 2).
TEST(GoggleRender, UnknownClassOrPhosphorIsRefused) {
  const fs::path dir = fs::temp_directory_path() / ("skyig_goggle_bad_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  EXPECT_EQ(runSkyig("render --goggle C --png " + (dir / "a.png").string(), dir / "log"), 2);
  EXPECT_EQ(runSkyig("render --goggle A --phosphor P22 --png " + (dir / "b.png").string(), dir / "log"), 2);
  EXPECT_FALSE(fs::exists(dir / "a.png"));
  EXPECT_FALSE(fs::exists(dir / "b.png"));
  fs::remove_all(dir);
}
