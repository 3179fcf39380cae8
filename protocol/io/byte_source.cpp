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
  position_ = 0;
  if (!std::filesystem::is_regular_file(path, ec)) {
    stream_ = true;  // a FIFO or a pipe: its size is what has been read so far
    fillStreamTo(kStreamLookahead);
    return error_.empty();
  }
  const auto s = std::filesystem::file_size(path, ec);
  if (ec) {
    error_ = path + ": " + ec.message();
    return false;
  }
  size_ = s;
  return true;
}

void FileSource::fillStreamTo(std::uint64_t end) {
  std::uint8_t chunk[65536];
  while (!streamEnded_ && size_ < end) {
    const std::size_t n = std::fread(chunk, 1, static_cast<std::size_t>(std::min<std::uint64_t>(sizeof chunk, end - size_)), file_);
    window_.insert(window_.end(), chunk, chunk + n);
    size_ += n;
    if (n == 0) {
      if (std::ferror(file_) != 0) error_ = path_ + ": read at byte " + std::to_string(size_) + ": " + std::strerror(errno);
      streamEnded_ = true;
    }
  }
}

std::size_t FileSource::readAt(std::uint64_t offset, std::span<std::uint8_t> dst) {
  if (file_ != nullptr && stream_ && !dst.empty()) {
    if (offset < windowStart_) {
      error_ = path_ + ": a stream (FIFO or pipe) cannot be read again at byte " + std::to_string(offset) +
               " (kept from byte " + std::to_string(windowStart_) + ")";
      return 0;
    }
    fillStreamTo(offset + dst.size() + kStreamLookahead);
    if (offset >= size_) return 0;
    const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(dst.size(), size_ - offset));
    std::memcpy(dst.data(), window_.data() + (offset - windowStart_), n);
    // Forget what lies well behind the reader (erased in large steps: amortised O(1) a byte).
    if (offset > windowStart_ + 2 * kStreamKeep) {
      const std::uint64_t drop = offset - kStreamKeep - windowStart_;
      window_.erase(window_.begin(), window_.begin() + static_cast<std::ptrdiff_t>(drop));
      windowStart_ += drop;
    }
    return n;
  }
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
