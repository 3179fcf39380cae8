#include "calibration/mpcdi_archive.h"

#include "calibration/calibration_error.h"

#include <zip.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>

namespace skyig::calibration {

namespace {

namespace fs = std::filesystem;

std::vector<std::uint8_t> slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw CalibrationError(p.string() + ": cannot open");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool startsWithZipMagic(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  char magic[4] = {};
  in.read(magic, 4);
  return in.gcount() == 4 && magic[0] == 'P' && magic[1] == 'K' && magic[2] == 3 && magic[3] == 4;
}

struct ZipCloser {
  void operator()(zip_t* z) const { zip_discard(z); }
};

std::unique_ptr<zip_t, ZipCloser> openZip(const std::string& path) {
  int error = 0;
  zip_t* z = zip_open(path.c_str(), ZIP_RDONLY, &error);
  if (!z) {
    zip_error_t e;
    zip_error_init_with_code(&e, error);
    const std::string message = zip_error_strerror(&e);
    zip_error_fini(&e);
    throw CalibrationError(path + ": not a readable MPCDI zip archive: " + message);
  }
  return std::unique_ptr<zip_t, ZipCloser>(z);
}

}  // namespace

MpcdiArchive::MpcdiArchive(const std::string& path) : path_(path) {
  std::error_code ec;
  const fs::path p(path);
  if (fs::is_directory(p, ec)) {
    folder_ = path;
    xmlName_ = "mpcdi.xml";
    if (!fs::is_regular_file(p / xmlName_, ec)) throw CalibrationError(path + ": the folder holds no mpcdi.xml");
    return;
  }
  if (!fs::is_regular_file(p, ec))
    throw CalibrationError(path + ": no such MPCDI file (a dome's is made by `skyig dome --out " + path + "`)");
  if (startsWithZipMagic(p)) {
    zip_ = true;
    const auto z = openZip(path);
    // The standard names it mpcdi.xml at the root; a single .xml anywhere is accepted too.
    if (zip_name_locate(z.get(), "mpcdi.xml", ZIP_FL_NOCASE) >= 0) {
      xmlName_ = "mpcdi.xml";
      return;
    }
    const zip_int64_t n = zip_get_num_entries(z.get(), 0);
    for (zip_int64_t i = 0; i < n; ++i) {
      const std::string name = zip_get_name(z.get(), static_cast<zip_uint64_t>(i), 0);
      if (name.size() > 4 && name.substr(name.size() - 4) == ".xml") {
        if (!xmlName_.empty()) throw CalibrationError(path + ": the archive holds no mpcdi.xml but several XML files");
        xmlName_ = name;
      }
    }
    if (xmlName_.empty()) throw CalibrationError(path + ": the zip archive holds no mpcdi.xml");
    return;
  }
  // An XML file on its own; its files beside it.
  folder_ = p.parent_path().empty() ? "." : p.parent_path().string();
  xmlName_ = p.filename().string();
}

std::string MpcdiArchive::describe(const std::string& member) const {
  if (!zip_ && member == xmlName_) return (fs::path(folder_) / member).string();
  return zip_ ? path_ + ":" + member : (fs::path(folder_) / member).string();
}

std::vector<std::uint8_t> MpcdiArchive::read(const std::string& member, std::uint64_t maxBytes,
                                             const std::string& what) const {
  if (member.empty()) throw CalibrationError(path_ + ": an empty file name");
  // The XML names files inside the calibration: an absolute path or one that climbs out of it
  // would read whatever file the name points at.
  const fs::path relative(member);
  if (relative.is_absolute() || std::any_of(relative.begin(), relative.end(), [](const fs::path& part) { return part == ".."; }))
    throw CalibrationError(describe(member) + ": a path outside the calibration (named by " + xmlName_ + ")");
  const auto tooLarge = [&](std::uint64_t size) {
    return CalibrationError(describe(member) + ": " + std::to_string(size) + " bytes, more than the " +
                            std::to_string(maxBytes) + " " + what + " can need");
  };
  if (!zip_) {
    std::error_code ec;
    const fs::path p = fs::path(folder_) / member;
    if (!fs::is_regular_file(p, ec)) throw CalibrationError(describe(member) + ": no such file (named by " + xmlName_ + ")");
    const std::uintmax_t size = fs::file_size(p, ec);
    if (!ec && size > maxBytes) throw tooLarge(size);
    return slurp(p);
  }
  const auto z = openZip(path_);
  zip_stat_t st;
  if (zip_stat(z.get(), member.c_str(), ZIP_FL_NOCASE, &st) != 0 || !(st.valid & ZIP_STAT_SIZE))
    throw CalibrationError(describe(member) + ": not in the archive (named by " + xmlName_ + ")");
  if (st.size > maxBytes) throw tooLarge(st.size);
  zip_file_t* f = zip_fopen(z.get(), member.c_str(), ZIP_FL_NOCASE);
  if (!f) throw CalibrationError(describe(member) + ": cannot be opened in the archive");
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(st.size));
  const zip_int64_t got = zip_fread(f, bytes.data(), st.size);
  zip_fclose(f);
  if (got < 0 || static_cast<zip_uint64_t>(got) != st.size)
    throw CalibrationError(describe(member) + ": the archive is damaged (read " + std::to_string(got) + " of " +
                           std::to_string(st.size) + " bytes)");
  return bytes;
}

}  // namespace skyig::calibration
