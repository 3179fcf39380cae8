#include "render/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace skyig::render {

namespace fs = std::filesystem;

namespace {

std::string errorText(int error) { return std::strerror(error); }

// Follows symbolic links to the file they name (which may not exist yet); relative targets
// are taken from the link's own directory.
fs::path resolveLinks(const std::string& path) {
  fs::path p(path);
  for (int hops = 0; hops < 40; ++hops) {
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(p, ec))) return p;
    const fs::path target = fs::read_symlink(p, ec);
    if (ec) throw OutputPathError("cannot follow the link " + path + ": " + ec.message());
    p = target.is_absolute() ? target : p.parent_path() / target;
  }
  throw OutputPathError("cannot follow the link " + path + ": too many levels of links");
}

enum class Kind { kFile, kInPlace };  // replaced atomically, or written where it is

// What `target` (links resolved) is as an output; throws OutputPathError for what cannot be.
Kind classify(const std::string& path, const fs::path& target) {
  struct stat st {};
  if (::stat(target.c_str(), &st) != 0) {
    if (errno != ENOENT) throw OutputPathError("cannot write " + path + ": " + errorText(errno));
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
      throw OutputPathError("cannot write " + path + ": directory " + dir.string() + " does not exist");
    if (::access(dir.c_str(), W_OK) != 0) throw OutputPathError("cannot write " + path + ": " + errorText(errno));
    return Kind::kFile;
  }
  if (S_ISDIR(st.st_mode)) throw OutputPathError("output path " + path + " is a directory");
  if (S_ISBLK(st.st_mode)) throw OutputPathError("output path " + path + " is a block device: refusing to write it");
  if (S_ISSOCK(st.st_mode)) throw OutputPathError("output path " + path + " is a socket");
  if (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode)) {
    if (::access(target.c_str(), W_OK) != 0) throw OutputPathError("cannot write " + path + ": " + errorText(errno));
    return Kind::kInPlace;
  }
  // A regular file is replaced through its directory.
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (::access(dir.c_str(), W_OK) != 0) throw OutputPathError("cannot write " + path + ": " + errorText(errno));
  return Kind::kFile;
}

// Writes everything or returns the errno of the failure.
int writeAll(int fd, std::span<const std::byte> bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errno : ENOSPC;
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

}  // namespace

void checkOutputPath(const std::string& path) {
  if (path.empty()) throw OutputPathError("empty output path");
  if (path == "-") return;
  classify(path, resolveLinks(path));
}

void writeOutputFile(const std::string& path, std::span<const std::byte> bytes) {
  if (path.empty()) throw OutputPathError("empty output path");
  if (path == "-") {
    if (const int e = writeAll(STDOUT_FILENO, bytes))
      throw OutputWriteError("cannot write to standard output: " + errorText(e));
    return;
  }
  const fs::path target = resolveLinks(path);
  if (classify(path, target) == Kind::kInPlace) {
    const int fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) throw OutputWriteError("cannot write " + path + ": " + errorText(errno));
    const int e = writeAll(fd, bytes);
    const int closed = ::close(fd) == 0 ? 0 : errno;
    if (e || closed) throw OutputWriteError("cannot write " + path + ": " + errorText(e ? e : closed));
    return;
  }
  const std::string tmp = target.string() + ".tmp-" + std::to_string(::getpid());
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw OutputWriteError("cannot write " + path + ": " + errorText(errno));
  int e = writeAll(fd, bytes);
  if (::close(fd) != 0 && !e) e = errno;
  if (!e && ::rename(tmp.c_str(), target.c_str()) != 0) e = errno;
  if (e) {
    ::unlink(tmp.c_str());  // the previous file stays as it was
    throw OutputWriteError("cannot write " + path + ": " + errorText(e));
  }
}

int openOutputStream(const std::string& path) {
  if (path.empty()) throw OutputPathError("empty output path");
  if (path == "-") {
    const int fd = ::fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 0);
    if (fd < 0) throw OutputPathError("cannot write to standard output: " + errorText(errno));
    return fd;
  }
  const fs::path target = resolveLinks(path);
  const Kind kind = classify(path, target);
  const int fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC | (kind == Kind::kFile ? O_CREAT | O_TRUNC : 0), 0644);
  if (fd < 0) throw OutputPathError("cannot write " + path + ": " + errorText(errno));
  return fd;
}

void checkDistinctOutputs(const std::vector<std::pair<std::string, std::string>>& outputs) {
  auto identity = [](const std::string& path) {
    if (path == "-") return std::string("-");
    std::error_code ec;
    const fs::path resolved = fs::weakly_canonical(resolveLinks(path), ec);
    return (ec ? fs::absolute(path) : resolved).string();
  };
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if (outputs[i].second.empty()) continue;
    for (std::size_t j = 0; j < i; ++j) {
      if (outputs[j].second.empty()) continue;
      if (identity(outputs[i].second) == identity(outputs[j].second))
        throw OutputPathError(outputs[j].first + " and " + outputs[i].first + " name the same file, " +
                              outputs[i].second + ": give each output its own");
    }
  }
}

}  // namespace skyig::render
