#include "ephemeris/data_files.h"

#include <dlfcn.h>

#include <cstdlib>
#include <system_error>

namespace skyig::ephemeris {

namespace {

const char* dataDirEnvironment() {
  const char* dir = std::getenv("SKYIG_DATA_DIR");
  return dir && *dir ? dir : nullptr;
}

std::filesystem::path runningExecutable() {
  std::error_code ec;
  std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : exe;
}

// The shared library this code was linked into (libskyig.so), or empty when it is part of an
// executable: the file dladdr names for one of its own functions.
std::filesystem::path containingLibrary() {
  Dl_info info{};
  if (!dladdr(reinterpret_cast<void*>(&containingLibrary), &info) || !info.dli_fname) return {};
  const std::filesystem::path file = info.dli_fname;
  if (file.filename().string().find(".so") == std::string::npos) return {};
  std::error_code ec;
  const std::filesystem::path canonical = std::filesystem::canonical(file, ec);
  return ec ? file : canonical;
}

}  // namespace

std::filesystem::path dataDirectory(const char* environment, const std::filesystem::path& executable,
                                    const std::filesystem::path& library) {
  if (environment && *environment) return environment;
  if (!library.empty()) return (library.parent_path() / SKYIG_LIBRARY_TO_DATA).lexically_normal();
  if (executable.empty()) return {};
  return (executable.parent_path() / ".." / "share" / "skyig").lexically_normal();
}

std::filesystem::path dataDirectory() {
  const char* environment = dataDirEnvironment();
  const std::filesystem::path library = environment ? std::filesystem::path() : containingLibrary();
  std::filesystem::path dir =
      dataDirectory(environment, environment || !library.empty() ? std::filesystem::path() : runningExecutable(), library);
  if (dir.empty())
    throw DataFileError("skyig's data directory is unknown: SKYIG_DATA_DIR is not set and /proc/self/exe cannot be read");
  return dir;
}

std::string dataFilePath(const std::string& name) { return (dataDirectory() / name).string(); }

std::string requireDataFile(const std::string& name) {
  const std::string path = dataFilePath(name);
  std::error_code ec;
  if (std::filesystem::is_regular_file(path, ec)) return path;
  const std::string how = dataDirEnvironment()           ? "the data directory is $SKYIG_DATA_DIR"
                         : !containingLibrary().empty() ? "SKYIG_DATA_DIR is not set, so the data directory is <libskyig.so's directory>/" SKYIG_LIBRARY_TO_DATA
                                                        : "SKYIG_DATA_DIR is not set, so the data directory is <executable's directory>/../share/skyig";
  throw DataFileError("data file " + name + " not found at " + path + " (" + how +
                      "; set SKYIG_DATA_DIR to the directory that holds skyig's data files)");
}

}  // namespace skyig::ephemeris
