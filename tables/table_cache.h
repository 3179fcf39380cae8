#pragma once
// Disk cache of the precomputed tables, keyed by the parameter hash (parameter_hash.h). A
// file that is missing, truncated, corrupt (checksum), from another format or physics
// revision, or made with other parameters is reported and rebuilt, never trusted.
//
// File layout (little-endian), extension .skyatm:
//   offset  size  field
//        0     8  magic "SKYIGATM"
//        8     4  format version (kCacheFormatVersion)
//       12     4  physics revision (kPhysicsRevision)
//       16     8  parameter hash
//       24     4  group count (groups of four wavelengths)
//       28    32  table sizes, 8 x int32: transmittance mu, r; irradiance mu_s, r;
//                 scattering r, mu, mu_s, nu
//       60     4  scalar type: 1 = float32
//       64     8  payload size in bytes
//       72     8  FNV-1a 64 checksum of the payload
//       80     -  payload: for each group, the transmittance (as the optical depth tau to the
//                 top; version 1 held exp(-tau)), irradiance, scattering and single Mie
//                 tables in that order, texels x fastest, each RGBA float32
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "physics/atmosphere/model.h"
#include "physics/atmosphere/precompute/precompute_control.h"

namespace skyig::atmosphere {

inline constexpr std::uint32_t kCacheFormatVersion = 2;
inline constexpr std::size_t kCacheHeaderBytes = 80;

std::filesystem::path cacheFilePath(const std::filesystem::path& directory,
                                    const ModelConfig& config);

// Writes atomically (temporary file, then rename), so a reader never sees half a file.
// Throws std::runtime_error naming the path on I/O failure.
void writeTableCache(const std::filesystem::path& path, const ModelConfig& config,
                     const std::vector<GroupTables>& tables);

// The tables, or nullopt with *reason saying why the file was not usable.
std::optional<std::vector<GroupTables>> readTableCache(const std::filesystem::path& path,
                                                       const ModelConfig& config,
                                                       std::string* reason);

// Rounds every texel to float32, the cache's precision, so a model is the same whether it
// was just computed or loaded.
void roundTablesToFloat(std::vector<GroupTables>& tables);

enum class CacheOutcome { kLoaded, kComputed, kRebuilt };

struct CacheResult {
  CacheOutcome outcome;
  std::string reason;  // why the cache was not used (kComputed, kRebuilt)
  std::filesystem::path path;
  // Why tables computed here could not be kept (a full or read-only cache): they are used all
  // the same, and no temporary file is left. Empty when they were cached or loaded.
  std::string writeError = {};
};

// Computes the tables of every group of a config. The CPU reference is the default; the GPU
// precompute (render/passes/precompute/atmosphere_gpu_precompute.h) is one too, passed in by code that may use
// GL (this library must not). Either may throw; the cache key does not say which one made a
// file (the GPU tables are within 0.3% of the CPU ones: docs/atmosphere.md). A builder stops
// with Cancelled when control.cancel is set and names its steps to control.step.
using TableBuilder = std::function<std::vector<GroupTables>(const ModelConfig&, const PrecomputeControl&)>;

// The CPU precompute (precompute.h) of every group; steps are named "group 2/4: ...".
std::vector<GroupTables> precomputeTablesOnCpu(const ModelConfig& config, const PrecomputeControl& control = {});

// Loads the model's tables from `directory` if a valid file matches the config (and touches
// it: its modification time is its last use); otherwise precomputes them (with `builder`, the
// CPU by default), writes the file and returns the model. With maxCacheBytes > 0 the files
// least recently used are then removed until the cache holds at most that many bytes
// (evictLeastRecentlyUsed); the file just written stays whatever its size. While another
// process computes the same file this waits for it; `control.cancel` ends the wait and the
// precompute alike (Cancelled, nothing written).
AtmosphereModel loadOrPrecompute(const ModelConfig& config,
                                 const std::filesystem::path& directory,
                                 CacheResult* result = nullptr);
AtmosphereModel loadOrPrecompute(const ModelConfig& config,
                                 const std::filesystem::path& directory, CacheResult* result,
                                 const TableBuilder& builder, std::uint64_t maxCacheBytes = 0,
                                 const PrecomputeControl& control = {});

// True when `directory` has a file for the config (valid or not: reading it costs as much as
// loading it).
bool cacheFileExists(const std::filesystem::path& directory, const ModelConfig& config);

// Removes the least recently used cache files (*.skyatm, oldest modification time first) and
// their lock files until the *.skyatm files of `directory` total at most maxBytes; never
// `keep`. Returns the files removed. A file another process still reads stays readable to it
// (POSIX unlink); one it needs again is computed again.
std::vector<std::filesystem::path> evictLeastRecentlyUsed(const std::filesystem::path& directory,
                                                          std::uint64_t maxBytes,
                                                          const std::filesystem::path& keep);

}  // namespace skyig::atmosphere
