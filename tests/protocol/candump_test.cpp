// candump logs: the can-utils line format both ways, unparseable lines named by line number
// and byte offset, skipping, and a CANaerospace state replayed from a log.
#include <gtest/gtest.h>

#include "protocol/canaerospace/state_decoder.h"
#include "protocol/canaerospace/state_encoder.h"
#include "protocol/candump/candump.h"

namespace skyig::protocol::candump {
namespace {

using canaerospace::kCanEffFlag;
using canaerospace::kCanErrFlag;
using canaerospace::kCanRtrFlag;

std::vector<std::uint8_t> bytes(std::string_view s) { return {s.begin(), s.end()}; }

TEST(Candump, FormatsLinesAsCandumpDoes) {
  CanFrame f;
  f.canId = 0x137;
  f.len = 8;
  f.data = {0x0A, 0x02, 0x00, 0x00, 0x40, 0x80, 0x00, 0x00};
  EXPECT_EQ(formatLine(1782073800000000, "can0", f), "(1782073800.000000) can0 137#0A02000040800000\n");
  f.canId = 0x12345678 | kCanEffFlag;
  f.len = 2;
  f.data = {0xDE, 0xAD};
  EXPECT_EQ(formatLine(1700000000123456, "vcan1", f), "(1700000000.123456) vcan1 12345678#DEAD\n");
  f.canId = 0x7FF | kCanRtrFlag;
  f.len = 0;
  EXPECT_EQ(formatLine(5, "can0", f), "(0000000000.000005) can0 7FF#R\n");
  f.len = 5;
  EXPECT_EQ(formatLine(5, "can0", f), "(0000000000.000005) can0 7FF#R5\n");
  f.canId = 0x00000080 | kCanErrFlag;
  f.len = 8;
  f.data = {};
  EXPECT_EQ(formatLine(5, "can0", f), "(0000000000.000005) can0 20000080#0000000000000000\n");
}

TEST(Candump, ParsesEveryFrameKindBack) {
  std::string why;
  auto r = parseLine("(1700000000.123456) can0 137#0A02000040800000", &why);
  ASSERT_TRUE(r) << why;
  EXPECT_EQ(r->timestampUs, 1700000000123456);
  EXPECT_EQ(r->interface, "can0");
  EXPECT_EQ(r->frame.canId, 0x137u);
  EXPECT_EQ(r->frame.len, 8);
  EXPECT_EQ(r->frame.data[4], 0x40);
  r = parseLine("(1.5) can1 12345678#11.22.33", &why);
  ASSERT_TRUE(r) << why;
  EXPECT_EQ(r->timestampUs, 1500000);
  EXPECT_EQ(r->frame.canId, 0x12345678u | kCanEffFlag);
  EXPECT_EQ(r->frame.len, 3);
  EXPECT_EQ(r->frame.data[2], 0x33);
  r = parseLine("(1.000000) can0 123#R3", &why);
  ASSERT_TRUE(r) << why;
  EXPECT_EQ(r->frame.canId, 0x123u | kCanRtrFlag);
  EXPECT_EQ(r->frame.len, 3);
  r = parseLine("(1.000000) can0 20000080#0000000000000000", &why);
  ASSERT_TRUE(r) << why;
  EXPECT_EQ(r->frame.canId, 0x20000080u);  // error frame: ERR flag, no EFF flag
  r = parseLine("(1.000000) can0 123#", &why);
  ASSERT_TRUE(r) << why;
  EXPECT_EQ(r->frame.len, 0);
  r = parseLine("(1.000000) can0 123#AB R\r", &why);  // trailing token and CR ignored
  ASSERT_TRUE(r) << why;
  EXPECT_EQ(r->frame.len, 1);
}

TEST(Candump, RejectsWhatDoesNotParse) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"1700000000.1 can0 137#00", "expected '('"},
      {"(17x.1) can0 137#00", "bad timestamp"},
      {"(1.1) can0", "interface name and a frame"},
      {"(1.1) can0 1370000", "has no '#'"},
      {"(1.1) can0 1234#00", "3 (11-bit) or 8 (29-bit)"},
      {"(1.1) can0 800#00", "exceeds 7FF"},
      {"(1.1) can0 G37#00", "not hexadecimal"},
      {"(1.1) can0 137#0", "odd number"},
      {"(1.1) can0 137#0X", "not hexadecimal"},
      {"(1.1) can0 137#000102030405060708", "longer than 8 bytes"},
      {"(1.1) can0 137##1AABB", "CAN FD"},
      {"(1.1) can0 C0000000#00", "reserved flag bits"},
  };
  for (const auto& [line, expected] : cases) {
    std::string why;
    EXPECT_FALSE(parseLine(line, &why).has_value()) << line;
    EXPECT_NE(why.find(expected), std::string::npos) << line << " -> " << why;
  }
}

TEST(Candump, ReaderNamesTheBadLineAndCanSkipIt) {
  const auto log = bytes(
      "(1700000000.000000) can0 137#0A02000040800000\n"
      "\n"
      "(1700000000.010000) can0 138#0A020000C1480000\n"
      "this is not a candump line\n"
      "(1700000000.020000) can0 141#0A020000C2B40000\n");
  io::MemorySource src(log);
  Reader r(src);
  Record rec;
  ASSERT_EQ(r.next(rec), Reader::Status::record);
  EXPECT_EQ(rec.line, 1u);
  ASSERT_EQ(r.next(rec), Reader::Status::record);
  EXPECT_EQ(rec.line, 3u);
  EXPECT_EQ(rec.offset, 47u);
  ASSERT_EQ(r.next(rec), Reader::Status::error);
  EXPECT_EQ(r.error().line, 4u);
  EXPECT_EQ(r.error().offset, 93u);
  EXPECT_NE(r.error().message.find("line 4 at byte 93"), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("\"this is not a candump line\""), std::string::npos) << r.error().message;

  io::MemorySource src2(log);
  Reader skip(src2, true);
  int n = 0;
  while (skip.next(rec) == Reader::Status::record) ++n;
  EXPECT_EQ(n, 3);
  EXPECT_EQ(skip.skipped(), 1u);
  EXPECT_EQ(rec.timestampUs, 1700000000020000);
}

TEST(Candump, ALogWithoutFinalNewlineAndAnEmptyLog) {
  const auto log = bytes("(1.000000) can0 137#0A02000040800000");
  io::MemorySource src(log);
  Reader r(src);
  Record rec;
  EXPECT_EQ(r.next(rec), Reader::Status::record);
  EXPECT_EQ(r.next(rec), Reader::Status::end);
  const std::vector<std::uint8_t> none;
  io::MemorySource empty(none);
  Reader e(empty);
  EXPECT_EQ(e.next(rec), Reader::Status::end);
}

TEST(Candump, CanaerospaceStateReplaysFromALog) {
  canaerospace::CanAerospaceState in;
  in.latitudeDeg = 47.450239871234;
  in.longitudeDeg = 8.561983475982;
  in.altitudeM = 432.0;
  in.headingDeg = 271.0;
  in.pitchDeg = 3.25;
  in.rollDeg = -12.5;
  in.hour = 21;
  in.minute = 14;
  in.second = 30;
  in.year = 2026;
  in.month = 6;
  in.day = 21;
  canaerospace::StateEncoder enc;
  io::MemorySink sink;
  Writer w(sink);
  std::int64_t t = 1782076470000000;
  for (const CanFrame& f : enc.encode(in)) ASSERT_TRUE(w.write(t += 1000, "can0", f)) << w.error();
  EXPECT_EQ(w.records(), 10u);

  io::MemorySource src(sink.data);
  Reader r(src);
  canaerospace::StateDecoder dec;
  Record rec;
  while (r.next(rec) == Reader::Status::record) ASSERT_TRUE(dec.feed(rec.frame).ok());
  const auto& s = dec.state();
  EXPECT_EQ(s.latitudeDeg, in.latitudeDeg);
  EXPECT_EQ(s.longitudeDeg, in.longitudeDeg);
  EXPECT_EQ(s.altitudeM, 432.0);
  EXPECT_EQ(s.headingDeg, 271.0);
  EXPECT_EQ(s.pitchDeg, 3.25);
  EXPECT_EQ(s.rollDeg, -12.5);
  EXPECT_EQ(s.minute, 14);
  EXPECT_EQ(s.day, 21);
  EXPECT_TRUE(s.has(0xFF));
}

TEST(Candump, WriterRejectsBadInterfaceNames) {
  io::MemorySink sink;
  Writer w(sink);
  EXPECT_FALSE(w.write(0, "can 0", CanFrame{}));
  EXPECT_NE(w.error().find("bad interface name"), std::string::npos);
}

}  // namespace
}  // namespace skyig::protocol::candump
