#pragma once
// Byte output for the recording writers. The writers hand the sink one complete record per
// write() call. FileSink writes unbuffered (each record is one write(2) into the kernel, so
// a crash of skyig loses nothing written), and when a write fails part way - a full disk -
// it cuts the file back to the end of the last complete record, so the file stays readable,
// and reports the error. Surviving power loss needs the data on the disk as well: a sink
// whose sync() calls fdatasync (node/, POSIX) does that; the writers call sync() at the
// interval their options give (docs/protocol.md, "Flush policy").
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

namespace skyig::protocol::io {

class ByteSink {
 public:
  virtual ~ByteSink() = default;
  // Writes all of `bytes` or nothing (as far as the sink can guarantee); false on error.
  virtual bool write(std::span<const std::uint8_t> bytes) = 0;
  // Pushes written data towards stable storage; false on error.
  virtual bool sync() { return true; }
  virtual std::string error() const { return {}; }
};

class MemorySink final : public ByteSink {
 public:
  bool write(std::span<const std::uint8_t> bytes) override {
    data.insert(data.end(), bytes.begin(), bytes.end());
    return true;
  }
  std::vector<std::uint8_t> data;
};

class FileSink final : public ByteSink {
 public:
  FileSink() = default;
  ~FileSink() override;
  FileSink(const FileSink&) = delete;
  FileSink& operator=(const FileSink&) = delete;

  // Creates (truncates) the file. false with error() naming the path and the reason.
  bool open(const std::string& path);
  bool write(std::span<const std::uint8_t> bytes) override;
  bool sync() override;  // fflush: standard C++ cannot fsync; see the header comment
  std::string error() const override { return error_; }
  std::uint64_t bytesWritten() const { return good_; }

 private:
  std::FILE* file_ = nullptr;
  std::string path_;
  std::string error_;
  std::uint64_t good_ = 0;  // bytes of complete records in the file
};

}  // namespace skyig::protocol::io
