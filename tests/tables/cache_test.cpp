// The parameter hash and the disk cache: determinism, round trip, and a corrupt or mismatched
// file detected and rebuilt, never trusted.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <thread>

#include "physics/atmosphere/conditions.h"
#include "tables/parameter_hash.h"
#include "shared_models.h"

namespace skyig::atmosphere {
namespace {

ModelConfig tinyConfig() {
  ModelConfig c = testing::oneGroupConfig();
  c.wavelengthsNm = {440.0, 550.0, 680.0, 700.0, 720.0};  // two groups, the last padded
  c.sizes = testing::tinySizes();
  c.options.scatteringOrders = 3;
  return c;
}

std::filesystem::path freshDirectory(const char* name) {
  const auto dir = testing::testCacheDirectory() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

bool sameTables(const AtmosphereModel& a, const AtmosphereModel& b) {
  if (a.groupCount() != b.groupCount()) return false;
  for (std::size_t g = 0; g < a.groupCount(); ++g) {
    const auto& x = a.tables(g);
    const auto& y = b.tables(g);
    if (x.transmittance.texels != y.transmittance.texels || x.irradiance.texels != y.irradiance.texels ||
        x.scattering.texels != y.scattering.texels || x.singleMie.texels != y.singleMie.texels) {
      return false;
    }
  }
  return true;
}

TEST(AtmosphereHash, Fnv1aKnownVectors) {
  // FNV-1a 64: "" -> cbf29ce484222325, "a" -> af63dc4c8601ec8c (IETF draft test vectors).
  Fnv1a64 empty;
  EXPECT_EQ(empty.value(), 0xcbf29ce484222325ull);
  Fnv1a64 a;
  a.bytes("a", 1);
  EXPECT_EQ(a.value(), 0xaf63dc4c8601ec8cull);
}

TEST(AtmosphereHash, EveryParameterChangesTheHash) {
  const ModelConfig base = tinyConfig();
  const std::uint64_t h0 = parameterHash(base);
  std::vector<ModelConfig> variants(20, base);
  variants[0].medium.bottomRadiusM += 1.0;
  variants[1].medium.topRadiusM += 1.0;
  variants[2].medium.rayleighScatteringAt1umPerM *= 1.001;
  variants[3].medium.rayleighScaleHeightM += 1.0;
  variants[4].medium.mieExtinctionPerM *= 1.001;
  variants[5].medium.mieSingleScatteringAlbedo = 0.91;
  variants[6].medium.mieAngstromExponent = 0.1;
  variants[7].medium.mieScaleHeightM += 1.0;
  variants[8].medium.miePhaseG = 0.76;
  variants[9].medium.ozoneColumnDu = 301.0;
  variants[10].medium.ozoneCentreAltitudeM += 1.0;
  variants[11].medium.ozoneHalfWidthM += 1.0;
  variants[12].medium.groundAlbedo = 0.3;
  variants[13].medium.sunAngularRadiusRad *= 1.01;
  variants[14].medium.solarIrradianceScale = 2.0;
  variants[15].medium.maxSunZenithRad -= 0.01;
  variants[16].wavelengthsNm.back() = 721.0;
  variants[17].sizes.scatteringNu = 4;
  variants[18].options.scatteringOrders = 2;
  variants[19].options.threads = 1;  // the only field that must NOT change the tables
  for (std::size_t i = 0; i + 1 < variants.size(); ++i) {
    EXPECT_NE(parameterHash(variants[i]), h0) << "variant " << i;
  }
  EXPECT_EQ(parameterHash(variants[19]), h0);
}

TEST(AtmosphereCache, PrecomputationIsDeterministicAcrossThreadCounts) {
  ModelConfig one = tinyConfig();
  one.options.threads = 1;
  ModelConfig three = tinyConfig();
  three.options.threads = 3;
  EXPECT_TRUE(sameTables(AtmosphereModel(one), AtmosphereModel(three)));
}

TEST(AtmosphereCache, RoundTripAndReuse) {
  const auto dir = freshDirectory("round_trip");
  const ModelConfig c = tinyConfig();
  CacheResult first;
  const AtmosphereModel computed = loadOrPrecompute(c, dir, &first);
  EXPECT_EQ(first.outcome, CacheOutcome::kComputed);
  EXPECT_TRUE(std::filesystem::exists(first.path));
  // Header size + 2 groups x (16x8 + 8x4 + 2 x 8x8x4) texels x 16 bytes.
  EXPECT_EQ(std::filesystem::file_size(first.path), kCacheHeaderBytes + 2 * (128 + 32 + 512) * 16);
  CacheResult second;
  const AtmosphereModel loaded = loadOrPrecompute(c, dir, &second);
  EXPECT_EQ(second.outcome, CacheOutcome::kLoaded);
  EXPECT_TRUE(sameTables(computed, loaded));
  // The computed model is the float-rounded one, so a cache hit changes nothing.
  ModelConfig direct = c;
  std::vector<GroupTables> raw;
  const AtmosphereModel fresh(direct);
  for (std::size_t g = 0; g < fresh.groupCount(); ++g) raw.push_back(fresh.tables(g));
  roundTablesToFloat(raw);
  EXPECT_TRUE(sameTables(computed, AtmosphereModel(c, raw)));
}

// With a bound of two and a half files, a third file evicts the least recently used one: a
// load counts as a use, so the older but reloaded file stays and the unused one goes.
TEST(AtmosphereCache, LeastRecentlyUsedTablesAreEvictedBeyondTheBound) {
  const auto dir = freshDirectory("lru");
  auto config = [](double albedo) {
    ModelConfig c = tinyConfig();
    c.medium.groundAlbedo = albedo;
    return c;
  };
  CacheResult a, b, c, again;
  loadOrPrecompute(config(0.1), dir, &a);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  loadOrPrecompute(config(0.2), dir, &b);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  loadOrPrecompute(config(0.1), dir, &again);  // 0.1 used after 0.2
  EXPECT_EQ(again.outcome, CacheOutcome::kLoaded);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const std::uint64_t fileBytes = std::filesystem::file_size(a.path);
  loadOrPrecompute(config(0.3), dir, &c, precomputeTablesOnCpu, fileBytes * 5 / 2);
  EXPECT_TRUE(std::filesystem::exists(a.path));
  EXPECT_FALSE(std::filesystem::exists(b.path));
  EXPECT_FALSE(std::filesystem::exists(b.path.string() + ".lock"));
  EXPECT_TRUE(std::filesystem::exists(c.path));
  // A bound below one file keeps the file just written, and only it.
  const auto removed = evictLeastRecentlyUsed(dir, 1, c.path);
  EXPECT_EQ(removed.size(), 1u);
  EXPECT_FALSE(std::filesystem::exists(a.path));
  EXPECT_TRUE(std::filesystem::exists(c.path));
}

TEST(AtmosphereCache, CorruptFileIsDetectedAndRebuilt) {
  const auto dir = freshDirectory("corrupt");
  const ModelConfig c = tinyConfig();
  CacheResult r;
  const AtmosphereModel good = loadOrPrecompute(c, dir, &r);
  const auto path = r.path;
  const auto size = std::filesystem::file_size(path);

  auto corrupt = [&](std::uintmax_t offset, char value) {
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(offset));
    f.put(value);
  };
  std::string reason;
  // A flipped payload byte: the checksum catches it.
  corrupt(size - 7, '\x5a');
  EXPECT_FALSE(readTableCache(path, c, &reason).has_value());
  EXPECT_NE(reason.find("checksum"), std::string::npos) << reason;
  CacheResult rebuilt;
  const AtmosphereModel again = loadOrPrecompute(c, dir, &rebuilt);
  EXPECT_EQ(rebuilt.outcome, CacheOutcome::kRebuilt);
  EXPECT_TRUE(sameTables(good, again));
  EXPECT_TRUE(readTableCache(path, c, &reason).has_value());

  // Wrong magic, truncation, another format version.
  corrupt(0, 'X');
  EXPECT_FALSE(readTableCache(path, c, &reason).has_value());
  EXPECT_NE(reason.find("not a skyig"), std::string::npos) << reason;
  loadOrPrecompute(c, dir);
  std::filesystem::resize_file(path, size - 100);
  EXPECT_FALSE(readTableCache(path, c, &reason).has_value());
  EXPECT_NE(reason.find("payload size"), std::string::npos) << reason;
  loadOrPrecompute(c, dir);
  corrupt(8, '\x7f');
  EXPECT_FALSE(readTableCache(path, c, &reason).has_value());
  EXPECT_NE(reason.find("format version"), std::string::npos) << reason;
}

TEST(AtmosphereCache, FileOfOtherParametersIsNotTrusted) {
  const auto dir = freshDirectory("mismatch");
  const ModelConfig c = tinyConfig();
  CacheResult r;
  loadOrPrecompute(c, dir, &r);
  // The same file presented for another ground albedo (e.g. renamed by hand).
  ModelConfig other = c;
  Conditions conditions;
  conditions.groundAlbedo = 0.3;
  other.medium = applyConditions(c.medium, conditions);
  std::string reason;
  EXPECT_FALSE(readTableCache(r.path, other, &reason).has_value());
  EXPECT_NE(reason.find("other parameters"), std::string::npos) << reason;
  EXPECT_NE(cacheFilePath(dir, other), r.path);
}

TEST(AtmosphereCache, BadConfigurationIsRejectedWithItsName) {
  ModelConfig c = tinyConfig();
  c.sizes.scatteringMu = 7;
  try {
    AtmosphereModel m(c);
    FAIL() << "odd scattering_mu accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("scattering_mu = 7"), std::string::npos) << e.what();
  }
  c = tinyConfig();
  c.medium.miePhaseG = 1.0;
  EXPECT_THROW(AtmosphereModel{c}, std::invalid_argument);
  c = tinyConfig();
  c.wavelengthsNm = {550.0, 440.0};
  EXPECT_THROW(AtmosphereModel{c}, std::invalid_argument);
  c = tinyConfig();
  c.options.scatteringOrders = 0;
  EXPECT_THROW(AtmosphereModel{c}, std::invalid_argument);
}

}  // namespace
}  // namespace skyig::atmosphere

using skyig::atmosphere::TableSizes;

// The named sizes: medium halves the default's radii and view angles and keeps the rest; small is
// the tests'; unknown names are refused with the three that exist.
TEST(AtmosphereTableSizes, NamedSizes) {
  const TableSizes medium = TableSizes::named("medium");
  const TableSizes full = TableSizes::named("default");
  EXPECT_EQ(medium.scatteringR * 2, full.scatteringR);
  EXPECT_EQ(medium.scatteringMu * 2, full.scatteringMu);
  EXPECT_EQ(medium.scatteringMuS, full.scatteringMuS);
  EXPECT_EQ(medium.scatteringNu, full.scatteringNu);
  EXPECT_EQ(medium.transmittanceMu, full.transmittanceMu);
  EXPECT_EQ(full.scatteringTexels(), 4 * medium.scatteringTexels());
  EXPECT_EQ(TableSizes::named("small").scatteringR, TableSizes::small().scatteringR);
  try {
    (void)TableSizes::named("huge");
    FAIL() << "accepted an unknown size";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("\"huge\""), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("\"medium\""), std::string::npos) << e.what();
  }
}
