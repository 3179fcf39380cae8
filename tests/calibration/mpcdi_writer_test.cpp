// The dome's MPCDI writer (calibration/mpcdi_writer.h) read back by the MPCDI reader
// (calibration/load.h): what the generator computed is what a node loads, in both profiles.
#include "calibration/dome.h"
#include "calibration/calibration_error.h"
#include "calibration/load.h"
#include "calibration/mpcdi_writer.h"
#include "calibration/png_map.h"

#include <gtest/gtest.h>
#include <tinyxml2.h>
#include <unistd.h>
#include <zip.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

using namespace skyig::calibration;

struct TempDir {
  std::filesystem::path path;
  TempDir() {
    path = std::filesystem::temp_directory_path() / ("skyig-mpcdi-writer-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
};

skyig::calibration::ProjectorSource source(const std::string& path, const std::string& region) {
  skyig::calibration::ProjectorSource s;
  s.mpcdiPath = path;
  s.region = region;
  return s;
}

Dome smallDome() {
  Dome dome = defaultHelicopterDome(160, 100);
  dome.warpStep = 8;
  return dome;
}

std::string writeTo(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary) << bytes;
  return file.string();
}

// One file of a zip, by name.
std::vector<std::uint8_t> toBytes(const std::string& s) { return {s.begin(), s.end()}; }

std::string zipEntry(const std::string& bytes, const std::string& name) {
  zip_error_t error;
  zip_error_init(&error);
  zip_source_t* src = zip_source_buffer_create(bytes.data(), bytes.size(), 0, &error);
  zip_t* archive = zip_open_from_source(src, ZIP_RDONLY, &error);
  EXPECT_NE(archive, nullptr);
  std::string out;
  if (archive == nullptr) return out;
  zip_stat_t st;
  if (zip_stat(archive, name.c_str(), 0, &st) == 0) {
    zip_file_t* f = zip_fopen(archive, name.c_str(), 0);
    out.resize(st.size);
    zip_fread(f, out.data(), st.size);
    zip_fclose(f);
  }
  zip_close(archive);
  zip_error_fini(&error);
  return out;
}

TEST(MpcdiWriter, TheXmlNamesEveryRegionWithItsFrustumAndFiles) {
  const Dome dome = smallDome();
  const auto cals = generateDome(dome);
  const std::string bytes = encodeMpcdi(dome, cals, {});
  tinyxml2::XMLDocument doc;
  const std::string xml = zipEntry(bytes, "mpcdi.xml");
  ASSERT_EQ(doc.Parse(xml.c_str()), tinyxml2::XML_SUCCESS) << xml;
  const auto* root = doc.RootElement();
  EXPECT_STREQ(root->Attribute("profile"), "2d");
  EXPECT_STREQ(root->Attribute("version"), "2.0");
  int regions = 0;
  for (const auto* b = root->FirstChildElement("display")->FirstChildElement("buffer"); b; b = b->NextSiblingElement("buffer")) {
    const auto* r = b->FirstChildElement("region");
    ASSERT_NE(r, nullptr);
    EXPECT_EQ(r->IntAttribute("xResolution"), 160);
    EXPECT_EQ(r->IntAttribute("yResolution"), 100);
    const auto* f = r->FirstChildElement("frustum");
    // MPCDI's left and down angles are negative (below and left of the view axis).
    EXPECT_LT(f->FirstChildElement("leftAngle")->DoubleText(), 0.0);
    EXPECT_LT(f->FirstChildElement("downAngle")->DoubleText(), 0.0);
    EXPECT_GT(f->FirstChildElement("rightAngle")->DoubleText(), 0.0);
    ++regions;
  }
  EXPECT_EQ(regions, 5);
  int filesets = 0;
  for (const auto* s = root->FirstChildElement("files")->FirstChildElement("fileset"); s; s = s->NextSiblingElement("fileset")) {
    const std::string region = s->Attribute("region");
    for (const char* map : {"geometryWarpFile", "alphaMap", "betaMap"}) {
      const std::string path = s->FirstChildElement(map)->FirstChildElement("path")->GetText();
      EXPECT_FALSE(zipEntry(bytes, path).empty()) << region << " " << map << " " << path;
    }
    EXPECT_DOUBLE_EQ(s->FirstChildElement("alphaMap")->FirstChildElement("gammaEmbedded")->DoubleText(), 2.2);
    ++filesets;
  }
  EXPECT_EQ(filesets, 5);
  // The alpha PNG holds alpha^(1/2.2): a half-lit pixel is stored brighter than half.
  const FloatMap stored = readPngMap(toBytes(zipEntry(bytes, "left_alpha.png")), "left_alpha.png", 1 << 14, 1 << 14);
  const FloatMap& alpha = cals[0].alpha;
  bool sawBlend = false;
  for (std::size_t k = 0; k < alpha.values.size(); ++k)
    if (alpha.values[k] > 0.2f && alpha.values[k] < 0.8f) {
      EXPECT_NEAR(stored.values[k], std::pow(alpha.values[k], 1.0f / 2.2f), 1e-4f);
      sawBlend = true;
    }
  EXPECT_TRUE(sawBlend);
}

// Written and read back, each region's camera, warp, alpha and beta are the generator's: the
// 2d warp to float precision, the a3 warp (dome points projected again by the reader) to a
// hundredth of a pixel, alpha and beta to their 16-bit steps.
void expectRoundTrip(MpcdiProfile profile, double warpTolerance) {
  TempDir dir;
  const Dome dome = smallDome();
  const auto cals = generateDome(dome);
  MpcdiWriteOptions options;
  options.profile = profile;
  const std::string path = writeTo(dir.path / "dome.mpcdi", encodeMpcdi(dome, cals, options));
  for (const ProjectorCalibration& cal : cals) {
    ProjectorSource source;
    source.mpcdiPath = path;
    source.region = cal.region;
    const ProjectorCalibration read = loadProjector(source);
    EXPECT_EQ(read.width, cal.width);
    EXPECT_EQ(read.height, cal.height);
    EXPECT_NEAR(read.camera.offset.yawDeg, cal.camera.offset.yawDeg, 1e-6) << cal.region;
    EXPECT_NEAR(read.camera.offset.pitchDeg, cal.camera.offset.pitchDeg, 1e-6) << cal.region;
    EXPECT_NEAR(read.camera.offset.rollDeg, cal.camera.offset.rollDeg, 1e-6) << cal.region;
    EXPECT_NEAR(read.camera.frustum.leftDeg, cal.camera.frustum.leftDeg, 1e-6) << cal.region;
    EXPECT_NEAR(read.camera.frustum.downDeg, cal.camera.frustum.downDeg, 1e-6) << cal.region;
    ASSERT_EQ(read.warp.width, cal.warp.width);
    ASSERT_EQ(read.warp.height, cal.warp.height);
    // 21 x 14 warp nodes for 160 x 100 pixels at every 8th pixel and the last.
    EXPECT_EQ(cal.warp.width, 21);
    EXPECT_EQ(cal.warp.height, 14);
    for (int j = 0; j < cal.warp.height; ++j)
      for (int i = 0; i < cal.warp.width; ++i)
        for (int c = 0; c < 2; ++c)
          ASSERT_NEAR(read.warp.at(i, j, c), cal.warp.at(i, j, c), warpTolerance) << cal.region << " " << i << "," << j;
    ASSERT_EQ(read.alpha.values.size(), cal.alpha.values.size());
    for (std::size_t k = 0; k < cal.alpha.values.size(); ++k) {
      // One 16-bit step of alpha^(1/2.2), in linear light: at most 2.2 / 65535 near alpha = 1.
      ASSERT_NEAR(read.alpha.values[k], cal.alpha.values[k], 4e-5f) << cal.region;
      ASSERT_NEAR(read.beta.values[k], cal.beta.values[k], 1.0f / 65535.0f) << cal.region;
    }
  }
}

TEST(MpcdiWriter, A2dFileReadsBackAsGenerated) { expectRoundTrip(MpcdiProfile::TwoD, 1e-6); }

TEST(MpcdiWriter, AnA3FileReadsBackAsGenerated) {
  // A hundredth of a 160-pixel image's width.
  expectRoundTrip(MpcdiProfile::A3, 0.01 / 160);
}

TEST(MpcdiWriter, AnUnknownProfileIsNamed) {
  try {
    parseMpcdiProfile("3dd");
    FAIL();
  } catch (const CalibrationError& e) {
    EXPECT_NE(std::string(e.what()).find("3dd"), std::string::npos);
  }
}

}  // namespace

namespace {

// The committed fixture (tests/data/calibration/dome5_small.mpcdi, made by
// `skyig dome --resolution 160x100 --warp-step 8`) is what the generator makes today: a change
// of the generator or the writer that would make it stale fails here.
TEST(MpcdiWriter, TheDomeFixtureIsWhatTheGeneratorMakes) {
  const std::string fixture = std::string(SKYIG_SOURCE_DIR) + "/tests/data/calibration/dome5_small.mpcdi";
  const auto cals = generateDome(smallDome());
  ASSERT_EQ(cals.size(), 5u);
  for (const ProjectorCalibration& cal : cals) {
    const ProjectorCalibration read = loadProjector(source(fixture, cal.region));
    EXPECT_NEAR(read.camera.offset.yawDeg, cal.camera.offset.yawDeg, 1e-6) << cal.region;
    EXPECT_NEAR(read.camera.frustum.upDeg, cal.camera.frustum.upDeg, 1e-6) << cal.region;
    ASSERT_EQ(read.warp.values.size(), cal.warp.values.size()) << cal.region;
    for (std::size_t k = 0; k < cal.warp.values.size(); ++k) ASSERT_NEAR(read.warp.values[k], cal.warp.values[k], 1e-6);
    for (std::size_t k = 0; k < cal.alpha.values.size(); ++k) ASSERT_NEAR(read.alpha.values[k], cal.alpha.values[k], 4e-5f);
  }
}

}  // namespace
