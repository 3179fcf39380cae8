// Calibration files that would starve or blind a node: a PNG header of 60000 x 60000 in a
// 100-byte file, a zip member that inflates to hundreds of megabytes, a warp or an XML padded to
// 3 GiB, warps of NaN, inf or 3e38, a PFM read in the wrong byte order, and truncated or flipped
// bytes of a real calibration. Each is loaded in a child process (fork) so that its exit and its
// peak resident memory (wait4's ru_maxrss) are measured: it loads (0) or is refused with a
// CalibrationError naming the file (2), never anything else, and never above 512 MB.
#include "calibration/calibration_error.h"
#include "calibration/load.h"
#include "calibration/pfm.h"

#include <gtest/gtest.h>
#include <zip.h>
#include <zlib.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace skyig::calibration;

const fs::path kData = fs::path(SKYIG_SOURCE_DIR) / "tests/data/calibration";
constexpr long kPeakRssLimitKb = 512 * 1024;

struct ChildLoad {
  int exitCode = -1;  // 0 loaded, 2 CalibrationError, 1 any other exception; -1 killed
  int signal = 0;
  long peakRssKb = 0;
  std::string message;  // the CalibrationError's, through a pipe
};

// Region p1 of `path` loaded in a child process.
ChildLoad loadInChild(const fs::path& path) {
  int fds[2];
  if (::pipe(fds) != 0) return {};
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(fds[0]);
    int code = 0;
    try {
      loadProjector(mpcdiSource(path.string(), "p1", WarpValues::Offset));
    } catch (const CalibrationError& e) {
      const ssize_t ignored = ::write(fds[1], e.what(), std::strlen(e.what()));
      (void)ignored;
      code = 2;
    } catch (...) {
      code = 1;
    }
    ::_exit(code);
  }
  ::close(fds[1]);
  ChildLoad r;
  char buf[4096];
  for (ssize_t n; (n = ::read(fds[0], buf, sizeof buf)) > 0;) r.message.append(buf, static_cast<std::size_t>(n));
  ::close(fds[0]);
  int status = 0;
  rusage usage{};
  ::wait4(pid, &status, 0, &usage);
  if (WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  r.peakRssKb = usage.ru_maxrss;
  return r;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeFile(const fs::path& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }

// A PNG of nothing but its signature, an IHDR saying width x height (8-bit grey) and IEND.
std::string pngHeaderOnly(std::uint32_t width, std::uint32_t height) {
  auto be32 = [](std::uint32_t v) {
    return std::string{static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8), static_cast<char>(v)};
  };
  auto chunk = [&](const std::string& type, const std::string& data) {
    const std::string body = type + data;
    const auto crc = static_cast<std::uint32_t>(::crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size())));
    return be32(static_cast<std::uint32_t>(data.size())) + body + be32(crc);
  };
  const std::string ihdr = be32(width) + be32(height) + std::string{8, 0, 0, 0, 0};
  return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IEND", "");
}

class HostileCalibration : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("skyig_hostile_" + std::to_string(::getpid()) + "_" + testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "p1");
    for (const char* f : {"mpcdi.xml", "p1/warp.pfm", "p1/alpha.png", "p1/beta.png"})
      fs::copy_file(kData / "warp_offset" / f, dir_ / f);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Refused with exit 2, the message naming `file` and saying `what`, under the memory limit.
  void expectRefused(const fs::path& path, const std::string& file, const std::string& what) {
    const ChildLoad r = loadInChild(path);
    EXPECT_EQ(r.exitCode, 2) << "signal " << r.signal << ": " << r.message;
    EXPECT_NE(r.message.find(file), std::string::npos) << r.message;
    EXPECT_NE(r.message.find(what), std::string::npos) << r.message;
    EXPECT_LT(r.peakRssKb, kPeakRssLimitKb) << r.message;
    std::printf("%-28s peak %5ld MB: %s\n", file.c_str(), r.peakRssKb / 1024, r.message.c_str());
  }

  // The fixture's warp (offsets, 9 x 6 x 3) with every value replaced by `value`.
  void writeWarpOf(float value, bool flipByteOrder = false) {
    FloatMap warp = readPfm([&] {
      const std::string s = slurp(dir_ / "p1/warp.pfm");
      return std::vector<std::uint8_t>(s.begin(), s.end());
    }(), "warp.pfm");
    if (!std::isnan(value) || !flipByteOrder)
      for (float& v : warp.values) v = value;
    std::vector<std::uint8_t> bytes = writePfm(warp, /*bigEndian=*/false);
    if (flipByteOrder) {  // little-endian floats under a scale that says big-endian
      const std::string text(bytes.begin(), bytes.end());
      const std::size_t at = text.find("-1");
      bytes[at] = ' ';
    }
    writeFile(dir_ / "p1/warp.pfm", std::string(bytes.begin(), bytes.end()));
  }

  fs::path dir_;
};

}  // namespace

TEST_F(HostileCalibration, PngHeadersLargerThanTheRegionAreRefusedBeforeDecoding) {
  writeFile(dir_ / "p1/alpha.png", pngHeaderOnly(60000, 60000));  // 7 GB decoded, 45 bytes of file
  expectRefused(dir_, "p1/alpha.png", "60000x60000 pixels, larger than the 64x40");
  writeFile(dir_ / "p1/alpha.png", pngHeaderOnly(1000000, 1000000));  // std::bad_alloc, naming no file, before
  expectRefused(dir_, "p1/alpha.png", "1000000x1000000");
  writeFile(dir_ / "p1/alpha.png", slurp(kData / "warp_offset/p1/alpha.png"));
  writeFile(dir_ / "p1/beta.png", pngHeaderOnly(20000, 20000));
  expectRefused(dir_, "p1/beta.png", "20000x20000");
}

TEST_F(HostileCalibration, FilesPaddedToGigabytesAreRefusedBySize) {
  // Sparse: 3 GiB on the file system, nothing on the disk.
  fs::resize_file(dir_ / "p1/warp.pfm", std::uintmax_t{3} << 30);
  expectRefused(dir_, "p1/warp.pfm", "3221225472 bytes, more than the");
  fs::copy_file(kData / "warp_offset/p1/warp.pfm", dir_ / "p1/warp.pfm", fs::copy_options::overwrite_existing);
  fs::resize_file(dir_ / "mpcdi.xml", std::uintmax_t{3} << 30);
  expectRefused(dir_, "mpcdi.xml", "bytes, more than the 16777216 an MPCDI XML can need");
}

TEST_F(HostileCalibration, AZipMemberThatInflatesPastTheRegionIsNotInflated) {
  // A 256 MiB warp of zeros in a zip of a few hundred kilobytes (a region of 64 x 40 needs 31 KB).
  const fs::path zeros = dir_ / "zeros.pfm";
  writeFile(zeros, "PF\n9 6\n-1.0\n");
  fs::resize_file(zeros, std::uintmax_t{256} << 20);
  const fs::path archive = dir_ / "bomb.mpcdi";
  int error = 0;
  zip_t* z = zip_open(archive.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  ASSERT_NE(z, nullptr);
  const std::string xml = slurp(dir_ / "mpcdi.xml");
  zip_source_t* xs = zip_source_buffer(z, xml.data(), xml.size(), 0);
  ASSERT_GE(zip_file_add(z, "mpcdi.xml", xs, ZIP_FL_OVERWRITE), 0);
  const zip_int64_t warp = zip_file_add(z, "p1/warp.pfm", zip_source_file(z, zeros.c_str(), 0, -1), ZIP_FL_OVERWRITE);
  ASSERT_GE(warp, 0);
  zip_set_file_compression(z, static_cast<zip_uint64_t>(warp), ZIP_CM_DEFLATE, 1);
  for (const char* f : {"p1/alpha.png", "p1/beta.png"}) {
    const std::string bytes = slurp(kData / "warp_offset" / f);
    char* copy = static_cast<char*>(std::malloc(bytes.size()));
    std::memcpy(copy, bytes.data(), bytes.size());
    ASSERT_GE(zip_file_add(z, f, zip_source_buffer(z, copy, bytes.size(), 1), ZIP_FL_OVERWRITE), 0);
  }
  ASSERT_EQ(zip_close(z), 0);
  EXPECT_LT(fs::file_size(archive), std::uintmax_t{4} << 20);
  expectRefused(archive, "bomb.mpcdi:p1/warp.pfm", "268435456 bytes, more than the");
}

TEST_F(HostileCalibration, WarpsWithNothingOnTheImageAreRefused) {
  writeWarpOf(std::numeric_limits<float>::quiet_NaN());
  expectRefused(dir_, "p1/warp.pfm", "none of the warp's 54 nodes lands on the image");
  writeWarpOf(std::numeric_limits<float>::infinity());
  expectRefused(dir_, "p1/warp.pfm", "none of the warp's 54 nodes lands on the image");
  writeWarpOf(3e38f);
  expectRefused(dir_, "p1/warp.pfm", "outside 1e-10..1e10 in magnitude: not a warp");
  writeWarpOf(2e5f);  // plausible floats, every node far off the image
  expectRefused(dir_, "p1/warp.pfm", "none of the warp's 54 nodes lands on the image");
  // The fixture's own offsets, little-endian, under a scale that says big-endian: every float
  // byte-swapped, tiny or huge.
  writeWarpOf(std::numeric_limits<float>::quiet_NaN(), /*flipByteOrder=*/true);
  const ChildLoad r = loadInChild(dir_);
  EXPECT_EQ(r.exitCode, 2) << r.message;
  EXPECT_NE(r.message.find("p1/warp.pfm"), std::string::npos) << r.message;
  std::printf("byte order flipped: %s\n", r.message.c_str());
}

TEST_F(HostileCalibration, TruncatedAndFlippedBytesLoadOrAreRefusedNeverWorse) {
  // The reference fixture zip, cut at every 8th byte and with 300 single bytes flipped (seeded):
  // every case loads or is refused with a CalibrationError, within the memory limit.
  const std::string good = slurp(kData / "warp_absolute.mpcdi");
  const fs::path path = dir_ / "case.mpcdi";
  std::mt19937 random(20261128);
  int loaded = 0, refused = 0;
  long peakKb = 0;
  auto run = [&](const std::string& bytes, const std::string& what) {
    writeFile(path, bytes);
    const ChildLoad r = loadInChild(path);
    EXPECT_TRUE(r.exitCode == 0 || r.exitCode == 2) << what << ": exit " << r.exitCode << ", signal " << r.signal;
    EXPECT_LT(r.peakRssKb, kPeakRssLimitKb) << what;
    if (r.exitCode == 2) {
      EXPECT_NE(r.message.find("case.mpcdi"), std::string::npos) << what << ": " << r.message;
    }
    (r.exitCode == 0 ? loaded : refused) += 1;
    peakKb = std::max(peakKb, r.peakRssKb);
  };
  for (std::size_t cut = 0; cut < good.size(); cut += 8) run(good.substr(0, cut), "cut at " + std::to_string(cut));
  for (int i = 0; i < 300; ++i) {
    std::string bytes = good;
    const std::size_t at = random() % bytes.size();
    bytes[at] = static_cast<char>(bytes[at] ^ static_cast<char>(1 + random() % 255));
    run(bytes, "byte " + std::to_string(at) + " flipped");
  }
  std::printf("%d cases loaded, %d refused, peak %ld MB\n", loaded, refused, peakKb / 1024);
  EXPECT_GT(refused, 0);
}
