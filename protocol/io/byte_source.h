#pragma once
// Random-access byte input for the recording readers: a file, or memory (tests, fuzzing).
// Random access lets the pcap reader step back and resynchronise after a corrupt record.
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

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
// A FIFO, a pipe or a character device (anything but a regular file) is read as a stream: the
// bytes are read as the readers ask for them, with kStreamLookahead bytes read ahead so size()
// (the bytes read so far, exact once the stream ends) covers any record a reader checks, and
// the last kStreamKeep bytes kept so a reader may step back (resynchronisation). Reading
// further back than that fails with an error.
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
  // False for a stream: it can be read once, front to back.
  bool seekable() const { return !stream_; }

  static constexpr std::uint64_t kStreamLookahead = 1u << 20;  // above any pcap(ng) record
  static constexpr std::uint64_t kStreamKeep = 1u << 20;

 private:
  void fillStreamTo(std::uint64_t end);

  std::FILE* file_ = nullptr;
  bool stream_ = false;
  std::vector<std::uint8_t> window_;  // a stream's bytes [windowStart_, windowStart_ + size)
  std::uint64_t windowStart_ = 0;
  bool streamEnded_ = false;
  std::uint64_t size_ = 0;
  std::uint64_t position_ = 0;
  std::string path_;
  std::string error_;
};

}  // namespace skyig::protocol::io
