// CIGI 3.3 messages: round trips of every packet type in both byte orders, and malformed
// input rejected with the right error kind and offset while earlier packets are kept.
#include <gtest/gtest.h>

#include "protocol/cigi/date.h"
#include "protocol/cigi/decoder.h"
#include "protocol/cigi/encoder.h"
#include "tests/protocol/cigi_samples.h"
#include "tests/protocol/hex.h"

namespace skyig::protocol::cigi {
namespace {

std::vector<std::uint8_t> hostMessage(ByteOrder order) {
  std::vector<std::uint8_t> b;
  const std::vector<Packet> packets = test::everyPacketType();
  EXPECT_EQ(encodeMessage(packets, order, b), "");
  return b;
}

TEST(CigiCodec, EveryPacketTypeRoundTripsInBothByteOrders) {
  const std::vector<Packet> packets = test::everyPacketType();
  ASSERT_EQ(packets.size(), kPacketTypeCount);
  for (ByteOrder order : {ByteOrder::big, ByteOrder::little}) {
    std::vector<std::uint8_t> b;
    ASSERT_EQ(encodeMessage(packets, order, b), "");
    EXPECT_EQ(b.size(), 24u + 48 + 32 + 16 + 32 + 48 + 56 + 32 + 32 + 24 + 24);
    const DecodedMessage d = decodeMessage(b);
    ASSERT_TRUE(d.ok()) << d.error->describe();
    EXPECT_EQ(d.byteOrder, order);
    ASSERT_EQ(d.packets.size(), packets.size());
    for (std::size_t i = 0; i < packets.size(); ++i)
      EXPECT_TRUE(d.packets[i] == packets[i]) << packetName(i) << " in " << toString(order);
  }
}

TEST(CigiCodec, ByteOrdersDifferOnlyInMultiByteFields) {
  const auto be = hostMessage(ByteOrder::big);
  const auto le = hostMessage(ByteOrder::little);
  ASSERT_EQ(be.size(), le.size());
  EXPECT_NE(be, le);
  // The Entity Control latitude (offset 24 of the packet at 24) is the 8 bytes reversed.
  for (int i = 0; i < 8; ++i) EXPECT_EQ(be[24 + 24 + i], le[24 + 24 + 7 - i]);
}

TEST(CigiCodec, UnknownPacketsAreSkippedBySizeAndCounted) {
  auto b = hostMessage(ByteOrder::big);
  // Insert a Component Control (id 4, 32 bytes) and a user-defined 8-byte packet (id 201)
  // after the IG Control.
  std::vector<std::uint8_t> extra(32, 0xAB);
  extra[0] = 4;
  extra[1] = 32;
  const std::vector<std::uint8_t> user{201, 8, 1, 2, 3, 4, 5, 6};
  b.insert(b.begin() + 24, user.begin(), user.end());
  b.insert(b.begin() + 24, extra.begin(), extra.end());
  const DecodedMessage d = decodeMessage(b);
  ASSERT_TRUE(d.ok()) << d.error->describe();
  EXPECT_EQ(d.skippedPackets, 2u);
  EXPECT_EQ(d.packets.size(), kPacketTypeCount);
}

TEST(CigiCodec, EmptyMessage) {
  const DecodedMessage d = decodeMessage(std::span<const std::uint8_t>{});
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.error->kind, ErrorKind::emptyMessage);
  EXPECT_TRUE(d.packets.empty());
}

TEST(CigiCodec, TruncatedMessageKeepsTheCompletePacketsBeforeIt) {
  const auto full = hostMessage(ByteOrder::little);
  // Cut inside the Rate Control packet (starts at 72): IG Control and Entity Control survive.
  const std::vector<std::uint8_t> cut(full.begin(), full.begin() + 80);
  const DecodedMessage d = decodeMessage(cut);
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.error->kind, ErrorKind::packetPastEnd);
  EXPECT_EQ(d.error->offset, 72u);
  EXPECT_EQ(d.error->packetId, 8);
  ASSERT_EQ(d.packets.size(), 2u);
  EXPECT_TRUE(std::holds_alternative<EntityControl>(d.packets[1]));
  EXPECT_NE(d.error->describe().find("at byte 72"), std::string::npos) << d.error->describe();
  EXPECT_NE(d.error->describe().find("Rate Control"), std::string::npos) << d.error->describe();

  // A single byte left after a complete packet: no room for a header.
  std::vector<std::uint8_t> tail(full.begin(), full.begin() + 72);
  tail.push_back(9);
  const DecodedMessage t = decodeMessage(tail);
  EXPECT_EQ(t.error->kind, ErrorKind::truncatedHeader);
  EXPECT_EQ(t.error->offset, 72u);
  EXPECT_EQ(t.packets.size(), 2u);

  // The IG Control itself cut short.
  const DecodedMessage h = decodeMessage(std::span(full.data(), 10));
  EXPECT_EQ(h.error->kind, ErrorKind::packetPastEnd);
  EXPECT_TRUE(h.packets.empty());
}

TEST(CigiCodec, WrongSizeOfAKnownPacketIsRejected) {
  auto b = hostMessage(ByteOrder::big);
  b[24 + 1] = 56;  // Entity Control claiming 56 bytes: oversized
  DecodedMessage d = decodeMessage(b);
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.error->kind, ErrorKind::wrongPacketSize);
  EXPECT_EQ(d.error->offset, 24u);
  EXPECT_EQ(d.error->value, 48u);
  EXPECT_EQ(d.packets.size(), 1u);
  EXPECT_NE(d.error->describe().find("expected 48 bytes"), std::string::npos);
  b[24 + 1] = 40;  // undersized
  d = decodeMessage(b);
  EXPECT_EQ(d.error->kind, ErrorKind::wrongPacketSize);
}

TEST(CigiCodec, ZeroPacketSizeCannotLoopForever) {
  auto b = hostMessage(ByteOrder::big);
  b[24 + 1] = 0;
  DecodedMessage d = decodeMessage(b);
  EXPECT_EQ(d.error->kind, ErrorKind::packetSizeTooSmall);
  EXPECT_EQ(d.error->offset, 24u);
  b[24] = 200;  // unknown id with size 1
  b[24 + 1] = 1;
  d = decodeMessage(b);
  EXPECT_EQ(d.error->kind, ErrorKind::packetSizeTooSmall);
}

TEST(CigiCodec, MessageMustBeginWithIgControlOrStartOfFrame) {
  auto b = hostMessage(ByteOrder::big);
  const std::vector<std::uint8_t> noIgControl(b.begin() + 24, b.end());
  const DecodedMessage d = decodeMessage(noIgControl);
  EXPECT_EQ(d.error->kind, ErrorKind::missingFirstPacket);
  EXPECT_EQ(d.error->packetId, 2);
  EXPECT_TRUE(d.packets.empty());
}

TEST(CigiCodec, WrongVersionsAreRejected) {
  auto b = hostMessage(ByteOrder::big);
  b[2] = 2;  // CIGI 2
  DecodedMessage d = decodeMessage(b);
  EXPECT_EQ(d.error->kind, ErrorKind::unsupportedVersion);
  EXPECT_EQ(d.error->value, 2u);
  EXPECT_NE(d.error->describe().find("major version 2"), std::string::npos);

  b = hostMessage(ByteOrder::big);
  b[4] = static_cast<std::uint8_t>((b[4] & 0x0F) | 0x10);  // minor version 1 in a 24-byte IG Control
  d = decodeMessage(b);
  EXPECT_EQ(d.error->kind, ErrorKind::unsupportedVersion);
  EXPECT_NE(d.error->describe().find("CIGI 3.1"), std::string::npos) << d.error->describe();

  b = hostMessage(ByteOrder::big);
  b[1] = 16;  // the 16-byte IG Control of CIGI 3.0/3.1
  d = decodeMessage(b);
  EXPECT_EQ(d.error->kind, ErrorKind::unsupportedVersion);

  // A CIGI 4-style header (u16 size 24, u16 id 0, little-endian) announcing major version 5.
  const auto v5 = protocol::test::hexBytes("18 00 00 00 05 00 00 00 | 01 00 00 00 00 00 00 00 | 00 00 00 00 00 00 00 00");
  d = decodeMessage(v5);
  EXPECT_EQ(d.error->kind, ErrorKind::unsupportedVersion);
  EXPECT_EQ(d.error->offset, 4u);
  EXPECT_NE(d.error->describe().find("major version 5"), std::string::npos) << d.error->describe();

  b = hostMessage(ByteOrder::big);
  b[2] = 200;  // garbage major version: not mistaken for a CIGI 3 minor version
  d = decodeMessage(b);
  EXPECT_NE(d.error->describe().find("major version 200"), std::string::npos) << d.error->describe();
}

TEST(CigiCodec, BadByteSwapMagicIsRejected) {
  auto b = hostMessage(ByteOrder::big);
  b[6] = 0x12;
  b[7] = 0x34;
  const DecodedMessage d = decodeMessage(b);
  EXPECT_EQ(d.error->kind, ErrorKind::badByteSwapMagic);
  EXPECT_EQ(d.error->offset, 6u);
  EXPECT_EQ(d.error->value, 0x1234u);
  EXPECT_NE(d.error->describe().find("0x1234"), std::string::npos);
}

TEST(CigiCodec, DecoderReusesItsStorage) {
  const auto b = hostMessage(ByteOrder::big);
  DecodedMessage d;
  decodeMessage(b, d);
  const auto* data = d.packets.data();
  decodeMessage(b, d);
  EXPECT_EQ(d.packets.data(), data);
  EXPECT_EQ(d.packets.size(), kPacketTypeCount);
}

TEST(CigiCodec, EncodeMessageChecksTheFirstPacket) {
  std::vector<std::uint8_t> b;
  const std::vector<Packet> bad{EntityControl{}};
  EXPECT_NE(encodeMessage(bad, ByteOrder::big, b).find("must begin with IG Control"), std::string::npos);
  EXPECT_TRUE(b.empty());
  EXPECT_FALSE(encodeMessage({}, ByteOrder::big, b).empty());
}

TEST(CigiDate, MmddyyyySplitsAndComposes) {
  EXPECT_EQ(splitDate(6212026), (CivilDate{2026, 6, 21}));
  EXPECT_EQ(composeDate({2026, 6, 21}), 6212026u);
  EXPECT_EQ(composeDate({2024, 2, 29}), 2292024u);
  EXPECT_FALSE(composeDate({2025, 2, 29}).has_value());
  EXPECT_FALSE(splitDate(13012026).has_value());  // month 13
  EXPECT_FALSE(splitDate(4312026).has_value());   // 31 April
  EXPECT_FALSE(splitDate(0).has_value());
  EXPECT_EQ(formatDate({2026, 6, 21}), "2026-06-21");
}

}  // namespace
}  // namespace skyig::protocol::cigi
