#include "protocol/io/byte_source.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

namespace skyig::protocol::io {

std::size_t MemorySource::readAt(std::uint64_t offset, std::span<std::uint8_t> dst) {
  if (offset >= bytes_.size() || dst.empty()) return 0;  // memcpy must not see a null dst
  const std::size_t n = std::min<std::uint64_t>(dst.size(), bytes_.size() - offset);
  std::memcpy(dst.data(), bytes_.data() + offset, n);
  return n;
}

FileSource::~FileSource() {
  if (file_ != nullptr) std::fclose(file_);
}

bool FileSource::open(const std::string& path) {
  path_ = path;
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    error_ = path + ": is a directory";
    return false;
  }
  file_ = std::fopen(path.c_str(), "rb");
  if (file_ == nullptr) {
    error_ = path + ": " + std::strerror(errno);
    return false;
  }
  const auto s = std::filesystem::file_size(path, ec);
  if (ec) {
    error_ = path + ": " + ec.message();
    return false;
  }
  size_ = s;
  position_ = 0;
  return true;
}

std::size_t FileSource::readAt(std::uint64_t offset, std::span<std::uint8_t> dst) {
  if (file_ == nullptr || offset >= size_ || dst.empty()) return 0;
  if (offset != position_) {
    if (std::fseek(file_, static_cast<long>(offset), SEEK_SET) != 0) {
      error_ = path_ + ": seek to byte " + std::to_string(offset) + ": " + std::strerror(errno);
      return 0;
    }
    position_ = offset;
  }
  const std::size_t n = std::fread(dst.data(), 1, dst.size(), file_);
  position_ += n;
  if (n < dst.size() && std::ferror(file_) != 0) {
    error_ = path_ + ": read at byte " + std::to_string(offset) + ": " + std::strerror(errno);
    std::clearerr(file_);
  }
  return n;
}

}  // namespace skyig::protocol::io
