#include "ephemeris/data_files.h"

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

}  // namespace

std::filesystem::path dataDirectory(const char* environment, const std::filesystem::path& executable) {
  if (environment && *environment) return environment;
  if (executable.empty()) return {};
  return (executable.parent_path() / ".." / "share" / "skyig").lexically_normal();
}

std::filesystem::path dataDirectory() {
  const char* environment = dataDirEnvironment();
  std::filesystem::path dir = dataDirectory(environment, environment ? std::filesystem::path() : runningExecutable());
  if (dir.empty())
    throw DataFileError("skyig's data directory is unknown: SKYIG_DATA_DIR is not set and /proc/self/exe cannot be read");
  return dir;
}

std::string dataFilePath(const std::string& name) { return (dataDirectory() / name).string(); }

std::string requireDataFile(const std::string& name) {
  const std::string path = dataFilePath(name);
  std::error_code ec;
  if (std::filesystem::is_regular_file(path, ec)) return path;
  const std::string how = dataDirEnvironment()
                              ? "the data directory is $SKYIG_DATA_DIR"
                              : "SKYIG_DATA_DIR is not set, so the data directory is <executable's directory>/../share/skyig";
  throw DataFileError("data file " + name + " not found at " + path + " (" + how +
                      "; set SKYIG_DATA_DIR to the directory that holds skyig's data files)");
}

}  // namespace skyig::ephemeris
