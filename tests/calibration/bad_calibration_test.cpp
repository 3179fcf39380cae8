// Every way a calibration file can be bad stops with one CalibrationError that names the file,
// where in it and the value -- what a configuration pointing at it prints before exit 2.
#include "calibration/load.h"
#include "calibration/pfm.h"

#include <gtest/gtest.h>

#include <cmath>
#include <zip.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using namespace skyig::calibration;

const fs::path kData = fs::path(SKYIG_SOURCE_DIR) / "tests/data/calibration";

class BadCalibration : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("skyig_calibration_" + std::to_string(::getpid()) + "_" + testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "p1");
    for (const char* f : {"p1/warp.pfm", "p1/alpha.png", "p1/beta.png"}) fs::copy_file(kData / "warp_offset" / f, dir_ / f);
    std::ifstream in(kData / "warp_offset/mpcdi.xml");
    xml_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    std::ofstream(dir_ / "mpcdi.xml") << xml_;  // the good file, until a test spoils it
  }
  void TearDown() override { fs::remove_all(dir_); }

  // The fixture's XML with `from` replaced by `to`.
  void writeXml(const std::string& from, const std::string& to) {
    std::string text = xml_;
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    std::ofstream(dir_ / "mpcdi.xml") << text;
  }
  void writeFile(const std::string& name, const std::string& bytes) { std::ofstream(dir_ / name, std::ios::binary) << bytes; }

  // The message loading region `region` gives; fails the test when it loads.
  std::string error(const std::string& region = "p1", const std::string& path = "") {
    try {
      loadProjector(mpcdiSource(path.empty() ? dir_.string() : path, region, WarpValues::Offset));
    } catch (const CalibrationError& e) {
      return e.what();
    }
    ADD_FAILURE() << "the bad file loaded";
    return "";
  }

  fs::path dir_;
  std::string xml_;
};

// VESA's reference library (the MPCDI SDK) writes the resolutions as Xresolution and
// Yresolution, and 0 for a gammaEmbedded it never set (its reader ignores it): read as the
// standard's xResolution, and as no gamma with a warning naming the line.
TEST_F(BadCalibration, TheReferenceLibrarysSpellingsAreRead) {
  std::string text = xml_;
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"xResolution", "Xresolution"},
                                 {"yResolution", "Yresolution"},
                                 {"<gammaEmbedded>2.2</gammaEmbedded>", "<gammaEmbedded>0</gammaEmbedded>"}})
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
      text.replace(at, from.size(), to);
  std::ofstream(dir_ / "mpcdi.xml") << text;
  const ProjectorCalibration p = loadProjector(mpcdiSource(dir_.string(), "p1", WarpValues::Offset));
  EXPECT_EQ(p.width, 64);
  EXPECT_EQ(p.height, 40);
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_NE(p.warnings[0].find("mpcdi.xml:13: region \"p1\": <gammaEmbedded> 0 read as not given"), std::string::npos)
      << p.warnings[0];
  // Read without the gamma: the stored alpha itself, where the file's 2.2 was taken out.
  const ProjectorCalibration withGamma = loadProjector(mpcdiSource((kData / "warp_offset").string(), "p1", WarpValues::Offset));
  EXPECT_TRUE(withGamma.warnings.empty());
  EXPECT_NEAR(p.alpha.at(12, 3), std::pow(withGamma.alpha.at(12, 3), 1.0 / 2.2), 1e-4);
}

// A configuration naming a calibration that is not there yet (config/dome5-projectors.toml
// before `skyig dome`) says how to make one.
TEST_F(BadCalibration, AMissingFileSaysHowToMakeADome) {
  const std::string e = error("p1", (dir_ / "dome5.mpcdi").string());
  EXPECT_NE(e.find("dome5.mpcdi: no such MPCDI file (a dome's is made by `skyig dome --out "), std::string::npos) << e;
}

TEST_F(BadCalibration, AMissingRegionListsTheRegionsThereAre) {
  const std::string e = error("p9");
  EXPECT_NE(e.find("mpcdi.xml"), std::string::npos) << e;
  EXPECT_NE(e.find("no region \"p9\" (the file has: p1)"), std::string::npos) << e;
}

TEST_F(BadCalibration, ANanFrustumAngleNamesItsLineAndElement) {
  writeXml("<yaw>10.0</yaw>", "<yaw>nan</yaw>");
  const std::string e = error();
  EXPECT_TRUE(std::regex_search(e, std::regex(R"(mpcdi\.xml:\d+: .*<frustum> <yaw> expected a finite number, got "nan")"))) << e;
}

TEST_F(BadCalibration, AnImpossibleFrustumIsRefused) {
  writeXml("<rightAngle>25.0</rightAngle>", "<rightAngle>-35.0</rightAngle>");
  EXPECT_NE(error().find("rightAngle -35.000000 is not to the right of leftAngle -30.000000"), std::string::npos);
  writeXml("<upAngle>20.0</upAngle>", "<upAngle>95.0</upAngle>");
  EXPECT_NE(error().find("within +-89"), std::string::npos);
}

TEST_F(BadCalibration, AThreeDProfileWithoutAFrustumIsRefused) {
  const auto from = xml_.find("<frustum>"), to = xml_.find("</frustum>") + 10;
  writeXml(xml_.substr(from, to - from), "");
  EXPECT_NE(error().find("<frustum> missing: profile 3d"), std::string::npos);
}

TEST_F(BadCalibration, ATruncatedWarpNamesTheFileAndTheBytes) {
  const std::string pfm = [&] {
    std::ifstream in(dir_ / "p1/warp.pfm", std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }();
  writeFile("p1/warp.pfm", pfm.substr(0, pfm.size() - 7));
  const std::string e = error();
  EXPECT_NE(e.find("p1/warp.pfm: PFM data: truncated"), std::string::npos) << e;
}

TEST_F(BadCalibration, MapsThatDoNotFitTheRegionAreRefused) {
  FloatMap big{100, 3, 3, std::vector<float>(900, 0.5f)};
  const auto bytes = writePfm(big);
  writeFile("p1/warp.pfm", std::string(bytes.begin(), bytes.end()));
  EXPECT_NE(error().find("a 100x3 warp does not fit region \"p1\" of 64x40 pixels"), std::string::npos);
}

TEST_F(BadCalibration, AMissingMapFileNamesTheFileAndTheXml) {
  fs::remove(dir_ / "p1/alpha.png");
  const std::string e = error();
  EXPECT_NE(e.find("p1/alpha.png: no such file (named by mpcdi.xml)"), std::string::npos) << e;
}

TEST_F(BadCalibration, APathOutsideTheCalibrationIsRefused) {
  writeXml("<path>p1/alpha.png</path>", "<path>../../etc/passwd</path>");
  EXPECT_NE(error().find("../../etc/passwd: a path outside the calibration"), std::string::npos);
  writeXml("<path>p1/alpha.png</path>", "<path>/etc/passwd</path>");
  EXPECT_NE(error().find("/etc/passwd: a path outside the calibration"), std::string::npos);
}

TEST_F(BadCalibration, AnAlphaMapThatIsNotAPngIsRefused) {
  writeFile("p1/alpha.png", "GIF89a not a png");
  EXPECT_NE(error().find("p1/alpha.png: not a PNG file"), std::string::npos);
}

TEST_F(BadCalibration, AnUnknownProfileIsRefused) {
  writeXml("profile=\"3d\"", "profile=\"4d\"");
  EXPECT_NE(error().find("<MPCDI profile=\"4d\">: expected the profile 2d, 3d, a3 or sl"), std::string::npos);
}

TEST_F(BadCalibration, MalformedXmlSaysWhere) {
  writeXml("</display>", "</displayy>");
  EXPECT_TRUE(std::regex_search(error(), std::regex(R"(mpcdi\.xml:\d+: malformed XML)")));
}

// A region's own problem (its file set's gamma, its frustum) refuses that region only: a channel
// naming another region of the same file loads.
TEST_F(BadCalibration, ABadRegionRefusesOnlyItself) {
  const auto regionFrom = xml_.find("<region id=\"p1\""), regionTo = xml_.find("</region>") + 9;
  const std::string p1 = xml_.substr(regionFrom, regionTo - regionFrom);
  std::string p2 = p1;
  p2.replace(p2.find("id=\"p1\""), 7, "id=\"p2\"");
  const auto setFrom = xml_.find("<fileset region=\"p1\">"), setTo = xml_.find("</fileset>") + 10;
  std::string set2 = xml_.substr(setFrom, setTo - setFrom);
  set2.replace(set2.find("region=\"p1\""), 11, "region=\"p2\"");
  const auto gamma = set2.find("<gammaEmbedded>");
  ASSERT_NE(gamma, std::string::npos);
  set2.replace(gamma, set2.find("</gammaEmbedded>") - gamma, "<gammaEmbedded>50");
  std::string text = xml_;
  text.insert(text.find("</fileset>") + 10, set2);
  text.insert(text.find("</region>") + 9, p2);
  std::ofstream(dir_ / "mpcdi.xml") << text;
  EXPECT_NO_THROW(loadProjector(mpcdiSource(dir_.string(), "p1", WarpValues::Offset)));
  const std::string e = error("p2");
  EXPECT_NE(e.find("<gammaEmbedded> 50.000000 is not a gamma from 0.1 to 10"), std::string::npos) << e;
  // A frustum of region p2 turned inside out: p1 still loads.
  std::string badFrustum = text;
  const auto p2At = badFrustum.find("id=\"p2\"");
  const auto right = badFrustum.find("<rightAngle>25.0</rightAngle>", p2At);
  ASSERT_NE(right, std::string::npos);
  badFrustum.replace(right, 29, "<rightAngle>-35.0</rightAngle>");
  std::ofstream(dir_ / "mpcdi.xml") << badFrustum;
  EXPECT_NO_THROW(loadProjector(mpcdiSource(dir_.string(), "p1", WarpValues::Offset)));
  EXPECT_NE(error("p2").find("rightAngle -35.000000 is not to the right of leftAngle"), std::string::npos);
}

TEST_F(BadCalibration, AFileSetForNoRegionIsRefused) {
  writeXml("<fileset region=\"p1\">", "<fileset region=\"p2\">");
  EXPECT_NE(error().find("names no region of the display (there are: p1)"), std::string::npos);
}

TEST_F(BadCalibration, PointsNeedThreeChannels) {
  writeXml("profile=\"3d\"", "profile=\"a3\"");
  FloatMap grey{9, 6, 1, std::vector<float>(54, 0.5f)};
  const auto bytes = writePfm(grey);
  writeFile("p1/warp.pfm", std::string(bytes.begin(), bytes.end()));
  EXPECT_NE(error().find("profile a3 needs 3D points"), std::string::npos);
}

TEST_F(BadCalibration, AZipWithoutMpcdiXmlIsRefused) {
  const std::string path = (dir_ / "empty.mpcdi").string();
  int err = 0;
  zip_t* z = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &err);
  ASSERT_TRUE(z);
  const char text[] = "hello";
  zip_source_t* s = zip_source_buffer(z, text, 5, 0);
  ASSERT_GE(zip_file_add(z, "readme.txt", s, ZIP_FL_OVERWRITE), 0);
  ASSERT_EQ(zip_close(z), 0);
  EXPECT_NE(error("p1", path).find("the zip archive holds no mpcdi.xml"), std::string::npos);
  writeFile("broken.mpcdi", "PK\x03\x04 and then nothing");
  EXPECT_NE(error("p1", (dir_ / "broken.mpcdi").string()).find("not a readable MPCDI zip archive"), std::string::npos);
}

TEST_F(BadCalibration, BourkeMeshErrorsNameTheLine) {
  const auto meshError = [&](const std::string& text) {
    writeFile("mesh.txt", text);
    try {
      loadProjector(bourkeSource((dir_ / "mesh.txt").string(), 64, 40));
    } catch (const CalibrationError& e) {
      return std::string(e.what());
    }
    return std::string("loaded");
  };
  EXPECT_NE(meshError("1\n2 2\n").find("mesh.txt:1: mesh type \"1\""), std::string::npos);
  EXPECT_NE(meshError("2\n2 2\n0 0 0 0 1\n1 0 1 0 1\n0 1 0\n").find("mesh.txt:5: node \"0 1 0\""), std::string::npos);
  EXPECT_NE(meshError("2\n2 2\n0 0 0 0 1\n1 0 1 0 1\n0 1 0 1 1\n").find("the file ends before all the nodes"),
            std::string::npos);
  EXPECT_NE(meshError("2\n2 2\n0 0 0 0 1\n1 0 1 0 1\n0.5 1 0 1 1\n1 1 1 1 1\n").find("off the rectangular grid"),
            std::string::npos);
  EXPECT_NE(meshError("2\n2 2\n-2e40 0 0 0 1\n").find("mesh.txt:3: node \"-2e40 0 0 0 1\": expected five numbers"),
            std::string::npos);
}

}  // namespace
