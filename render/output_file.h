#pragma once
// Files a user names as outputs (images, statistics, state dumps, recordings) are written
// without ever replacing what the name points at:
// - a regular file, or a name not there yet, is replaced atomically (PATH.tmp-PID beside it,
//   then renamed), so a reader never sees half a file and a failure leaves the previous one;
// - "-" is standard output; a FIFO or a character device (/dev/null) is opened and written in
//   place, never renamed over;
// - a symbolic link is followed to its target, which is written by these rules: the link stays;
// - a directory, a block device or a socket is refused.
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace skyig::render {

// The path cannot be an output: a directory, a missing directory, no permission, a block device,
// a socket, or two outputs naming one file. A usage error (exit 2); nothing was written.
class OutputPathError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writing failed (a full disk, an I/O error): a runtime error (exit 3). The message names the
// path; the previous file, where there was one, is intact and no temporary file is left.
class OutputWriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws OutputPathError if `path` cannot be written by the rules above (checked before work
// starts, so a bad output path fails fast and writes nothing).
void checkOutputPath(const std::string& path);

// Writes `bytes` to `path` by the rules above.
void writeOutputFile(const std::string& path, std::span<const std::byte> bytes);
inline void writeOutputFile(const std::string& path, const std::string& text) {
  writeOutputFile(path, std::as_bytes(std::span(text.data(), text.size())));
}

// A descriptor for an output written as it goes (a recording, a state dump): "-" is a
// duplicate of standard output; anything else is opened in place (created or truncated; a
// link's target; a FIFO or a character device as it is). Throws OutputPathError.
int openOutputStream(const std::string& path);

// Throws OutputPathError when two of `outputs` (flag, path) name the same file ("-" included):
// the second would silently replace the first.
void checkDistinctOutputs(const std::vector<std::pair<std::string, std::string>>& outputs);

}  // namespace skyig::render
