#pragma once
// Random-access byte input for the recording readers: a file, or memory (tests, fuzzing).
// Random access lets the pcap reader step back and resynchronise after a corrupt record.
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>

namespace skyig::protocol::io {

class ByteSource {
 public:
  virtual ~ByteSource() = default;
  virtual std::uint64_t size() const = 0;
  // Copies up to dst.size() bytes from `offset`; returns how many (fewer only at the end or
  // on an I/O error, which error() then describes).
  virtual std::size_t readAt(std::uint64_t offset, std::span<std::uint8_t> dst) = 0;
  virtual std::string error() const { return {}; }
};

class MemorySource final : public ByteSource {
 public:
  explicit MemorySource(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  std::uint64_t size() const override { return bytes_.size(); }
  std::size_t readAt(std::uint64_t offset, std::span<std::uint8_t> dst) override;

 private:
  std::span<const std::uint8_t> bytes_;
};

// A file opened read-only with stdio. open() fails with a message naming the path.
class FileSource final : public ByteSource {
 public:
  FileSource() = default;
  ~FileSource() override;
  FileSource(const FileSource&) = delete;
  FileSource& operator=(const FileSource&) = delete;

  bool open(const std::string& path);
  std::uint64_t size() const override { return size_; }
  std::size_t readAt(std::uint64_t offset, std::span<std::uint8_t> dst) override;
  std::string error() const override { return error_; }

 private:
  std::FILE* file_ = nullptr;
  std::uint64_t size_ = 0;
  std::uint64_t position_ = 0;
  std::string path_;
  std::string error_;
};

}  // namespace skyig::protocol::io
