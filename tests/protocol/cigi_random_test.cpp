// 100 000 random and mutated messages through the CIGI decoder: it never crashes, never
// reads out of bounds (run under ASan/UBSan or valgrind to see that), and every message
// ends either well-formed or with exactly one counted error kind.
#include <gtest/gtest.h>

#include <array>
#include <random>

#include "protocol/cigi/decoder.h"
#include "protocol/cigi/encoder.h"
#include "tests/protocol/cigi_samples.h"

namespace skyig::protocol::cigi {
namespace {

TEST(CigiRandom, HundredThousandMalformedMessagesAreCountedNotFatal) {
  std::mt19937 rng(20261122);
  std::vector<std::uint8_t> valid;
  ASSERT_EQ(encodeMessage(test::everyPacketType(), ByteOrder::little, valid), "");

  std::array<std::size_t, kErrorKindCount> errors{};
  std::size_t ok = 0;
  DecodedMessage d;
  std::vector<std::uint8_t> m;
  constexpr int kMessages = 100000;
  for (int i = 0; i < kMessages; ++i) {
    m = valid;
    switch (i % 4) {
      case 0: {  // flip a few random bytes
        const int flips = 1 + static_cast<int>(rng() % 4);
        for (int k = 0; k < flips; ++k) m[rng() % m.size()] = static_cast<std::uint8_t>(rng());
        break;
      }
      case 1:  // truncate anywhere
        m.resize(rng() % (m.size() + 1));
        break;
      case 2: {  // pure noise of random length
        m.resize(rng() % 600);
        for (auto& x : m) x = static_cast<std::uint8_t>(rng());
        break;
      }
      case 3: {  // valid header, then noise
        m.resize(24 + rng() % 400);
        for (std::size_t k = 24; k < m.size(); ++k) m[k] = static_cast<std::uint8_t>(rng());
        break;
      }
    }
    decodeMessage(m, d);
    if (d.ok()) {
      ++ok;
    } else {
      const auto k = static_cast<std::size_t>(d.error->kind);
      ASSERT_LT(k, kErrorKindCount);
      ++errors[k];
      ASSERT_LE(d.error->offset, m.size());
    }
    // Whatever was kept is whole packets that lie inside the message.
    std::size_t bytes = 0;
    for (const Packet& p : d.packets) bytes += packetSize(packetId(p));
    ASSERT_LE(bytes, m.size());
  }
  std::size_t total = ok;
  for (std::size_t e : errors) total += e;
  EXPECT_EQ(total, static_cast<std::size_t>(kMessages));
  // The mutation mix reaches every kind except the empty message only rarely; these must
  // all have been seen.
  EXPECT_GT(errors[static_cast<std::size_t>(ErrorKind::packetPastEnd)], 0u);
  EXPECT_GT(errors[static_cast<std::size_t>(ErrorKind::wrongPacketSize)], 0u);
  EXPECT_GT(errors[static_cast<std::size_t>(ErrorKind::missingFirstPacket)], 0u);
  EXPECT_GT(errors[static_cast<std::size_t>(ErrorKind::badByteSwapMagic)], 0u);
  EXPECT_GT(ok, 0u);  // byte flips inside float fields leave messages well-formed
  for (std::size_t k = 0; k < kErrorKindCount; ++k)
    std::printf("  %-58s %zu\n", toString(static_cast<ErrorKind>(k)), errors[k]);
  std::printf("  %-58s %zu\n", "well-formed", ok);
}

}  // namespace
}  // namespace skyig::protocol::cigi
