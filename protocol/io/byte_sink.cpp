#include "protocol/io/byte_sink.h"

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace skyig::protocol::io {

FileSink::~FileSink() {
  if (file_ != nullptr) std::fclose(file_);
}

bool FileSink::open(const std::string& path) {
  path_ = path;
  file_ = std::fopen(path.c_str(), "wb");
  if (file_ == nullptr) {
    error_ = path + ": " + std::strerror(errno);
    return false;
  }
  // Unbuffered: each record goes to the kernel in the write() call that hands it over.
  std::setvbuf(file_, nullptr, _IONBF, 0);
  good_ = 0;
  return true;
}

bool FileSink::write(std::span<const std::uint8_t> bytes) {
  if (file_ == nullptr) {
    if (error_.empty()) error_ = "file not open";
    return false;
  }
  if (!error_.empty()) return false;  // a failed sink stays failed: no records after a gap
  const std::size_t n = std::fwrite(bytes.data(), 1, bytes.size(), file_);
  if (n == bytes.size()) {
    good_ += n;
    return true;
  }
  const int err = errno;
  error_ = path_ + ": write failed after " + std::to_string(good_) + " bytes: " + std::strerror(err);
  // Cut a partial record off so the file ends with a complete one.
  std::fclose(file_);
  file_ = nullptr;
  std::error_code ec;
  std::filesystem::resize_file(path_, good_, ec);
  if (ec) error_ += " (and cutting back the partial record failed: " + ec.message() + ")";
  return false;
}

bool FileSink::sync() {
  if (file_ == nullptr) return false;
  if (std::fflush(file_) != 0) {
    error_ = path_ + ": flush failed: " + std::strerror(errno);
    return false;
  }
  return true;
}

}  // namespace skyig::protocol::io
