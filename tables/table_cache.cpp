#include "tables/table_cache.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <bit>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <thread>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include "tables/parameter_hash.h"
#include "physics/atmosphere/precompute/precompute.h"

namespace skyig::atmosphere {

static_assert(std::endian::native == std::endian::little,
              "the table cache is written in host order and documented little-endian");

namespace {

constexpr char kMagic[8] = {'S', 'K', 'Y', 'I', 'G', 'A', 'T', 'M'};
constexpr std::uint32_t kFloat32 = 1;

std::array<std::int32_t, 8> sizeArray(const TableSizes& s) {
  return {s.transmittanceMu, s.transmittanceR, s.irradianceMuS, s.irradianceR,
          s.scatteringR,     s.scatteringMu,   s.scatteringMuS, s.scatteringNu};
}

std::size_t groupTexels(const TableSizes& s) {
  return static_cast<std::size_t>(s.transmittanceMu) * static_cast<std::size_t>(s.transmittanceR) +
         static_cast<std::size_t>(s.irradianceMuS) * static_cast<std::size_t>(s.irradianceR) +
         2 * s.scatteringTexels();
}

std::size_t groupCount(const ModelConfig& c) { return (c.wavelengthsNm.size() + 3) / 4; }

template <typename T>
void put(std::vector<unsigned char>& out, const T& v) {
  const auto* p = reinterpret_cast<const unsigned char*>(&v);
  out.insert(out.end(), p, p + sizeof v);
}

template <typename T>
T get(const std::vector<unsigned char>& in, std::size_t offset) {
  T v;
  std::memcpy(&v, in.data() + offset, sizeof v);
  return v;
}

template <typename Fn>
void forEachTable(std::vector<GroupTables>& tables, Fn fn) {
  for (auto& g : tables) {
    fn(g.transmittance.texels);
    fn(g.irradiance.texels);
    fn(g.scattering.texels);
    fn(g.singleMie.texels);
  }
}

}  // namespace

std::filesystem::path cacheFilePath(const std::filesystem::path& directory,
                                    const ModelConfig& config) {
  return directory / ("atmosphere-" + hexHash(parameterHash(config)) + ".skyatm");
}

void roundTablesToFloat(std::vector<GroupTables>& tables) {
  forEachTable(tables, [](std::vector<glm::dvec4>& texels) {
    for (auto& t : texels) t = glm::dvec4(glm::vec4(t));
  });
}

void writeTableCache(const std::filesystem::path& path, const ModelConfig& config,
                     const std::vector<GroupTables>& tables) {
  std::vector<unsigned char> payload;
  payload.reserve(groupTexels(config.sizes) * tables.size() * 16);
  auto tablesCopy = tables;  // forEachTable wants mutable access; the copy is cheap enough
  forEachTable(tablesCopy, [&](std::vector<glm::dvec4>& texels) {
    for (const auto& t : texels) {
      for (int c = 0; c < 4; ++c) put(payload, static_cast<float>(t[c]));
    }
  });
  Fnv1a64 checksum;
  checksum.bytes(payload.data(), payload.size());

  std::vector<unsigned char> header(kMagic, kMagic + 8);
  header.reserve(kCacheHeaderBytes);
  put(header, kCacheFormatVersion);
  put(header, kPhysicsRevision);
  put(header, parameterHash(config));
  put(header, static_cast<std::uint32_t>(tables.size()));
  for (std::int32_t s : sizeArray(config.sizes)) put(header, s);
  put(header, kFloat32);
  put(header, static_cast<std::uint64_t>(payload.size()));
  put(header, checksum.value());
  if (header.size() != kCacheHeaderBytes) throw std::logic_error("table cache header size");

  std::error_code ec;
  std::filesystem::create_directories(path.parent_path(), ec);
  // Unique temporary name per thread and process, then an atomic rename.
  const auto tmp = path.string() + ".tmp" + std::to_string(::getpid()) + "-" +
                   std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id()));
  bool written = false;
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw std::runtime_error("atmosphere cache: cannot write " + tmp);
    f.write(reinterpret_cast<const char*>(header.data()), static_cast<std::streamsize>(header.size()));
    f.write(reinterpret_cast<const char*>(payload.data()), static_cast<std::streamsize>(payload.size()));
    f.flush();
    written = static_cast<bool>(f);
  }
  if (!written) {  // a full disk: the partial file would keep it full for every later start
    std::filesystem::remove(tmp, ec);
    throw std::runtime_error("atmosphere cache: write failed for " + tmp + " (disk full?)");
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw std::runtime_error("atmosphere cache: cannot rename into " + path.string());
  }
}

std::optional<std::vector<GroupTables>> readTableCache(const std::filesystem::path& path,
                                                       const ModelConfig& config,
                                                       std::string* reason) {
  auto fail = [&](const std::string& why) -> std::optional<std::vector<GroupTables>> {
    if (reason) *reason = path.string() + ": " + why;
    return std::nullopt;
  };
  std::ifstream f(path, std::ios::binary);
  if (!f) return fail("no such file");
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (bytes.size() < kCacheHeaderBytes) return fail("shorter than the header");
  if (std::memcmp(bytes.data(), kMagic, 8) != 0) return fail("not a skyig atmosphere cache");
  if (get<std::uint32_t>(bytes, 8) != kCacheFormatVersion) return fail("other format version");
  if (get<std::uint32_t>(bytes, 12) != kPhysicsRevision) return fail("other physics revision");
  if (get<std::uint64_t>(bytes, 16) != parameterHash(config)) return fail("other parameters");
  const std::size_t groups = groupCount(config);
  if (get<std::uint32_t>(bytes, 24) != groups) return fail("other wavelength group count");
  const auto sizes = sizeArray(config.sizes);
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    if (get<std::int32_t>(bytes, 28 + 4 * i) != sizes[i]) return fail("other table sizes");
  }
  if (get<std::uint32_t>(bytes, 60) != kFloat32) return fail("unknown scalar type");
  const std::size_t expected = groupTexels(config.sizes) * groups * 16;
  const auto payloadSize = get<std::uint64_t>(bytes, 64);
  if (payloadSize != expected || bytes.size() != kCacheHeaderBytes + expected) {
    return fail("payload size " + std::to_string(bytes.size() - kCacheHeaderBytes) +
                " bytes, expected " + std::to_string(expected));
  }
  Fnv1a64 checksum;
  checksum.bytes(bytes.data() + kCacheHeaderBytes, expected);
  if (checksum.value() != get<std::uint64_t>(bytes, 72)) return fail("checksum mismatch (corrupt)");

  const TableSizes& s = config.sizes;
  std::vector<GroupTables> tables(groups);
  for (auto& g : tables) {
    g.transmittance = shader::cpu_texture::sampler2D(s.transmittanceMu, s.transmittanceR);
    g.irradiance = shader::cpu_texture::sampler2D(s.irradianceMuS, s.irradianceR);
    g.scattering = shader::cpu_texture::sampler3D(s.scatteringNu * s.scatteringMuS,
                                                  s.scatteringMu, s.scatteringR);
    g.singleMie = g.scattering;
  }
  std::size_t offset = kCacheHeaderBytes;
  bool finite = true;
  forEachTable(tables, [&](std::vector<glm::dvec4>& texels) {
    for (auto& t : texels) {
      for (int c = 0; c < 4; ++c) {
        const float v = get<float>(bytes, offset);
        offset += 4;
        finite = finite && std::isfinite(v) && v >= 0.0f;
        t[c] = static_cast<double>(v);
      }
    }
  });
  if (!finite) return fail("negative, NaN or infinite values");
  return tables;
}

namespace {

// An exclusive advisory lock on `path`.lock for the scope: two processes needing the same
// tables (ctest -j, two skyig instances on a node) compute them once, the second one loads.
// The wait for it is polled so that a cancelled caller does not wait out the other's minutes.
class FileLock {
 public:
  FileLock(const std::filesystem::path& path, const CancelToken& cancel) {
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
    fd_ = ::open((path.string() + ".lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) return;  // no lock: still correct (atomic rename), just possibly computed twice
    while (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      if (errno != EWOULDBLOCK && errno != EINTR) {
        ::close(fd_);
        fd_ = -1;
        return;
      }
      if (cancel.requested()) {
        ::close(fd_);
        throw Cancelled();
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  }
  ~FileLock() {
    if (fd_ >= 0) ::close(fd_);  // closing releases the lock
  }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace

std::vector<GroupTables> precomputeTablesOnCpu(const ModelConfig& config, const PrecomputeControl& control) {
  const std::vector<AtmosphereParameters> groups = groupParameters(config);
  std::vector<GroupTables> tables;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    PrecomputeControl group{control.cancel, {}};
    if (control.step) {
      const std::string prefix = "group " + std::to_string(g + 1) + "/" + std::to_string(groups.size()) + ": ";
      group.step = [&](const std::string& name) { control.step(prefix + name); };
    }
    tables.push_back(precomputeGroup(groups[g], config.options, group));
  }
  return tables;
}

AtmosphereModel loadOrPrecompute(const ModelConfig& config,
                                 const std::filesystem::path& directory, CacheResult* result) {
  return loadOrPrecompute(config, directory, result, TableBuilder(precomputeTablesOnCpu));
}

AtmosphereModel loadOrPrecompute(const ModelConfig& config,
                                 const std::filesystem::path& directory, CacheResult* result,
                                 const TableBuilder& builder, std::uint64_t maxCacheBytes,
                                 const PrecomputeControl& control) {
  const auto path = cacheFilePath(directory, config);
  std::optional<AtmosphereModel> model;
  {
    const FileLock lock(path, control.cancel);
    std::string reason;
    if (auto tables = readTableCache(path, config, &reason)) {
      std::error_code ec;  // the last use, for least-recently-used eviction (best effort)
      std::filesystem::last_write_time(path, std::filesystem::file_time_type::clock::now(), ec);
      if (result) *result = {CacheOutcome::kLoaded, "", path, ""};
      return AtmosphereModel(config, std::move(*tables));
    }
    const bool existed = std::filesystem::exists(path);
    std::vector<GroupTables> tables = builder(config, control);  // validates the config (or throws)
    roundTablesToFloat(tables);
    std::string writeError;
    try {
      writeTableCache(path, config, tables);
    } catch (const std::runtime_error& e) {
      writeError = e.what();  // computed all the same: used, not kept
    }
    if (result) *result = {existed ? CacheOutcome::kRebuilt : CacheOutcome::kComputed, reason, path, writeError};
    model.emplace(config, std::move(tables));
  }  // unlocked before evicting: the lock files of evicted tables go too
  if (maxCacheBytes > 0) evictLeastRecentlyUsed(directory, maxCacheBytes, path);
  return std::move(*model);
}

bool cacheFileExists(const std::filesystem::path& directory, const ModelConfig& config) {
  std::error_code ec;
  return std::filesystem::exists(cacheFilePath(directory, config), ec);
}

std::vector<std::filesystem::path> evictLeastRecentlyUsed(const std::filesystem::path& directory,
                                                          std::uint64_t maxBytes,
                                                          const std::filesystem::path& keep) {
  struct Entry {
    std::filesystem::file_time_type used;
    std::uint64_t bytes;
    std::filesystem::path path;
  };
  std::vector<Entry> files;
  std::uint64_t total = 0;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(directory, ec)) {
    std::error_code fe;
    if (e.path().extension() != ".skyatm" || !e.is_regular_file(fe)) continue;
    const auto bytes = e.file_size(fe);
    const auto used = e.last_write_time(fe);
    if (fe) continue;  // removed meanwhile by another process
    files.push_back({used, bytes, e.path()});
    total += bytes;
  }
  std::sort(files.begin(), files.end(), [](const Entry& a, const Entry& b) { return a.used < b.used; });
  std::vector<std::filesystem::path> removed;
  for (const Entry& f : files) {
    if (total <= maxBytes) break;
    if (std::filesystem::equivalent(f.path, keep, ec)) continue;
    if (std::filesystem::remove(f.path, ec)) {
      std::filesystem::remove(f.path.string() + ".lock", ec);
      total -= f.bytes;
      removed.push_back(f.path);
    }
  }
  return removed;
}

}  // namespace skyig::atmosphere
