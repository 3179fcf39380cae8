#pragma once
// The files of an MPCDI calibration: a `.mpcdi` file is a zip archive of `mpcdi.xml` and the
// warp and blend files it names (VESA MPCDI v2, 2015); some tools write the same files into a
// folder instead, or hand over the XML alone beside its files. One reader for the three, so
// the parser never knows which it read.
#include <cstdint>
#include <string>
#include <vector>

namespace skyig::calibration {

// The largest mpcdi.xml read: the XML is kilobytes a region, so 16 MiB is thousands of regions.
inline constexpr std::uint64_t kMaxMpcdiXmlBytes = std::uint64_t{16} << 20;

class MpcdiArchive {
 public:
  // `path`: a zip archive, a folder holding mpcdi.xml, or an XML file (its files are found in
  // its folder). Throws CalibrationError naming the path when it is none of them.
  explicit MpcdiArchive(const std::string& path);

  const std::string& path() const { return path_; }
  // "dome.mpcdi:r1/warp.pfm", for messages.
  std::string describe(const std::string& member) const;
  // The XML's bytes.
  std::vector<std::uint8_t> xml() const { return read(xmlName_, kMaxMpcdiXmlBytes, "an MPCDI XML"); }
  const std::string& xmlName() const { return xmlName_; }
  // A member named by the XML (a path relative to the archive's root or the XML's folder).
  // Throws CalibrationError naming the archive and the member when it is not there, or when it
  // holds more than maxBytes, the most `what` can need (checked before a byte is read: a file by
  // its size, a zip member by the size the archive states, and no more than that is inflated).
  std::vector<std::uint8_t> read(const std::string& member, std::uint64_t maxBytes, const std::string& what) const;

 private:
  std::string path_;
  bool zip_ = false;
  std::string folder_;   // when not a zip: where members are
  std::string xmlName_;  // mpcdi.xml, or the XML's own file name
};

}  // namespace skyig::calibration
