// PFM bytes pinned by hand: the header, the scale's sign as the byte order, bottom-up rows.
#include "calibration/calibration_error.h"
#include "calibration/pfm.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

namespace {

using skyig::calibration::CalibrationError;
using skyig::calibration::FloatMap;
using skyig::calibration::readPfm;
using skyig::calibration::writePfm;

std::vector<std::uint8_t> bytesOf(const std::string& header, const std::vector<std::uint8_t>& data) {
  std::vector<std::uint8_t> b(header.begin(), header.end());
  b.insert(b.end(), data.begin(), data.end());
  return b;
}

// 1.0f = 3F800000, 2.0f = 40000000, 3.0f = 40400000, 4.0f = 40800000.
TEST(Pfm, LittleEndianRowsAreStoredBottomUp) {
  // A 2x2 grey map; the file's first row is the image's bottom row (3, 4).
  const auto file = bytesOf("Pf\n2 2\n-1.0\n", {0x00, 0x00, 0x40, 0x40, 0x00, 0x00, 0x80, 0x40,    // 3, 4
                                                0x00, 0x00, 0x80, 0x3F, 0x00, 0x00, 0x00, 0x40});  // 1, 2
  const FloatMap m = readPfm(file, "t.pfm");
  ASSERT_EQ(m.width, 2);
  ASSERT_EQ(m.height, 2);
  ASSERT_EQ(m.channels, 1);
  EXPECT_EQ(m.at(0, 0), 1.0f);  // top-left
  EXPECT_EQ(m.at(1, 0), 2.0f);
  EXPECT_EQ(m.at(0, 1), 3.0f);
  EXPECT_EQ(m.at(1, 1), 4.0f);
}

TEST(Pfm, APositiveScaleMeansBigEndian) {
  const auto file = bytesOf("PF 1 1 1.0\n", {0x3F, 0x80, 0x00, 0x00, 0x40, 0x00, 0x00, 0x00, 0x40, 0x40, 0x00, 0x00});
  const FloatMap m = readPfm(file, "t.pfm");
  ASSERT_EQ(m.channels, 3);
  EXPECT_EQ(m.at(0, 0, 0), 1.0f);
  EXPECT_EQ(m.at(0, 0, 1), 2.0f);
  EXPECT_EQ(m.at(0, 0, 2), 3.0f);
}

TEST(Pfm, WrittenBytesReadBackAndMatchTheHandWrittenLayout) {
  FloatMap m{2, 2, 1, {1.0f, 2.0f, 3.0f, 4.0f}};
  const auto bytes = writePfm(m);
  const auto expected = bytesOf("Pf\n2 2\n-1.0\n", {0x00, 0x00, 0x40, 0x40, 0x00, 0x00, 0x80, 0x40,
                                                    0x00, 0x00, 0x80, 0x3F, 0x00, 0x00, 0x00, 0x40});
  EXPECT_EQ(bytes, expected);
  FloatMap three{3, 1, 3, {1, 2, 3, 4, 5, 6, 7, 8, 9}};
  EXPECT_EQ(readPfm(writePfm(three, true), "big").values, three.values);
  EXPECT_EQ(readPfm(writePfm(three, false), "little").values, three.values);
}

TEST(Pfm, ATruncatedFileSaysHowManyBytesWereMissing) {
  const auto file = bytesOf("Pf\n2 2\n-1.0\n", {0x00, 0x00, 0x80, 0x3F});
  try {
    readPfm(file, "short.pfm");
    FAIL() << "a truncated PFM was read";
  } catch (const CalibrationError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("short.pfm"), std::string::npos) << what;
    EXPECT_NE(what.find("need 16 bytes, the file has 4"), std::string::npos) << what;
  }
}

TEST(Pfm, BadHeadersAreRefused) {
  for (const std::string header : {"P6\n2 2\n-1.0\n", "Pf\n0 2\n-1.0\n", "Pf\n2 2\nnan\n", "Pf\n2 2\n0\n", "Pf\n2"})
    EXPECT_THROW(readPfm(bytesOf(header, std::vector<std::uint8_t>(64, 0)), "h.pfm"), CalibrationError) << header;
}

}  // namespace
