// pcapng (what Wireshark and tshark write by default): sections, interfaces with their
// timestamp resolution, enhanced and simple packet blocks, other blocks skipped, corrupt
// blocks named and skipped; openCapture choosing the format by magic. Bytes built by hand
// from the pcapng block layouts (draft-ietf-opsawg-pcapng sections 4.1-4.4).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "protocol/io/byte_sink.h"
#include "protocol/io/byte_source.h"
#include "protocol/pcap/pcap_writer.h"
#include "protocol/pcap/pcapng_reader.h"
#include "tests/protocol/hex.h"
#include "tests/protocol/temp_path.h"

namespace skyig::protocol::pcap {
namespace {

using test::hexBytes;

// Little-endian pcapng blocks, each written out field by field.
std::vector<std::uint8_t> cat(std::initializer_list<std::vector<std::uint8_t>> parts) {
  std::vector<std::uint8_t> out;
  for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

// SHB: type 0A0D0D0A, length 28, magic 1A2B3C4D, version 1.0, section length -1, length.
const auto kShb = hexBytes("0A 0D 0D 0A 1C 00 00 00 4D 3C 2B 1A 01 00 00 00 FF FF FF FF FF FF FF FF 1C 00 00 00");
// IDB: type 1, length 32, link type 1 (Ethernet), reserved, snaplen 65535,
// option if_tsresol (9) length 1 value 9 (nanoseconds) + 3 pad, opt_endofopt, length.
const auto kIdbNano =
    hexBytes("01 00 00 00 20 00 00 00 01 00 00 00 FF FF 00 00 09 00 01 00 09 00 00 00 00 00 00 00 20 00 00 00");
// IDB without options (microseconds), link type 101 (raw IP).
const auto kIdbRaw = hexBytes("01 00 00 00 14 00 00 00 65 00 00 00 FF FF 00 00 14 00 00 00");

// EPB: type 6, length 32 + padded data, interface, timestamp high/low, captured, original, data.
std::vector<std::uint8_t> epb(std::uint32_t ifId, std::uint64_t ticks, std::vector<std::uint8_t> data) {
  const auto captured = static_cast<std::uint32_t>(data.size());
  while (data.size() % 4 != 0) data.push_back(0);
  const auto length = static_cast<std::uint32_t>(32 + data.size());
  std::vector<std::uint8_t> b(28);
  storeU32(&b[0], 6, ByteOrder::little);
  storeU32(&b[4], length, ByteOrder::little);
  storeU32(&b[8], ifId, ByteOrder::little);
  storeU32(&b[12], static_cast<std::uint32_t>(ticks >> 32), ByteOrder::little);
  storeU32(&b[16], static_cast<std::uint32_t>(ticks), ByteOrder::little);
  storeU32(&b[20], captured, ByteOrder::little);
  storeU32(&b[24], captured, ByteOrder::little);
  b.insert(b.end(), data.begin(), data.end());
  std::vector<std::uint8_t> tail(4);
  storeU32(tail.data(), length, ByteOrder::little);
  b.insert(b.end(), tail.begin(), tail.end());
  return b;
}

TEST(Pcapng, ReadsPacketsOfTwoInterfacesWithTheirResolutionAndLinkType) {
  // Name resolution block (type 4, 12 bytes, empty) must be skipped.
  const auto nrb = hexBytes("04 00 00 00 0C 00 00 00 0C 00 00 00");
  const auto file = cat({kShb, kIdbNano, kIdbRaw, epb(0, 1700000000123456789ull, {1, 2, 3}), nrb,
                         epb(1, 1700000000123456ull, {4, 5, 6, 7, 8})});
  io::MemorySource src(file);
  RecordError err;
  auto r = openCapture(src, false, err);
  ASSERT_NE(r, nullptr) << err.message;
  Record rec;
  ASSERT_EQ(r->next(rec), CaptureReader::Status::record) << r->error().message;
  EXPECT_EQ(rec.number, 1u);
  EXPECT_EQ(rec.linkType, kLinkEthernet);
  EXPECT_EQ(rec.timestampNs, 1700000000123456789);  // nanosecond interface
  EXPECT_EQ(rec.data, (std::vector<std::uint8_t>{1, 2, 3}));
  EXPECT_EQ(rec.offset, 28u + 32u + 20u);
  ASSERT_EQ(r->next(rec), CaptureReader::Status::record) << r->error().message;
  EXPECT_EQ(rec.linkType, kLinkRaw);
  EXPECT_EQ(rec.timestampNs, 1700000000123456000);  // microsecond default
  EXPECT_EQ(rec.data.size(), 5u);
  EXPECT_EQ(r->next(rec), CaptureReader::Status::end);
}

TEST(Pcapng, BigEndianSectionAndSimplePacket) {
  const auto shb = hexBytes("0A 0D 0D 0A 00 00 00 1C 1A 2B 3C 4D 00 01 00 00 FF FF FF FF FF FF FF FF 00 00 00 1C");
  const auto idb = hexBytes("00 00 00 01 00 00 00 14 00 01 00 00 00 00 FF FF 00 00 00 14");
  // SPB: type 3, length 20, original length 3, data 3 bytes + pad, length.
  const auto spb = hexBytes("00 00 00 03 00 00 00 14 00 00 00 03 AA BB CC 00 00 00 00 14");
  const auto file = cat({shb, idb, spb});
  io::MemorySource src(file);
  PcapngReader r(src);
  ASSERT_TRUE(r.open());
  Record rec;
  ASSERT_EQ(r.next(rec), CaptureReader::Status::record) << r.error().message;
  EXPECT_EQ(rec.data, (std::vector<std::uint8_t>{0xAA, 0xBB, 0xCC}));
  EXPECT_EQ(rec.linkType, kLinkEthernet);
}

TEST(Pcapng, CorruptBlockIsNamedAndSkipped) {
  auto file = cat({kShb, kIdbNano, epb(0, 1, {1}), epb(0, 2, {2, 2}), epb(0, 3, {3, 3, 3})});
  const std::size_t second = 28 + 32 + 36;
  file[second + 4] = 0xFF;  // block length 0x000000FF... not a multiple of 4
  {
    io::MemorySource src(file);
    PcapngReader r(src);
    ASSERT_TRUE(r.open());
    Record rec;
    ASSERT_EQ(r.next(rec), CaptureReader::Status::record);
    ASSERT_EQ(r.next(rec), CaptureReader::Status::error);
    EXPECT_EQ(r.error().kind, RecordError::Kind::badRecordHeader);
    EXPECT_EQ(r.error().offset, second);
    EXPECT_NE(r.error().message.find("block at byte " + std::to_string(second) + " (after packet 1)"),
              std::string::npos)
        << r.error().message;
  }
  io::MemorySource src(file);
  PcapngReader r(src, true);
  ASSERT_TRUE(r.open());
  Record rec;
  std::vector<std::uint8_t> firstBytes;
  while (r.next(rec) == CaptureReader::Status::record) firstBytes.push_back(rec.data[0]);
  EXPECT_EQ(firstBytes, (std::vector<std::uint8_t>{1, 3}));
  EXPECT_EQ(r.skipped(), 1u);

  // Cut inside the last block, as a crash while writing would.
  auto cut = cat({kShb, kIdbNano, epb(0, 1, {1}), epb(0, 2, {2, 2})});
  cut.resize(cut.size() - 6);
  io::MemorySource src2(cut);
  PcapngReader r2(src2);
  ASSERT_TRUE(r2.open());
  ASSERT_EQ(r2.next(rec), CaptureReader::Status::record);
  ASSERT_EQ(r2.next(rec), CaptureReader::Status::error);
  EXPECT_EQ(r2.error().kind, RecordError::Kind::truncatedRecord);
}

TEST(Pcapng, PacketBeforeAnyInterfaceIsAnError) {
  const auto file = cat({kShb, epb(0, 1, {1})});
  io::MemorySource src(file);
  PcapngReader r(src);
  ASSERT_TRUE(r.open());
  Record rec;
  ASSERT_EQ(r.next(rec), CaptureReader::Status::error);
  EXPECT_NE(r.error().message.find("interface 0 of 0"), std::string::npos) << r.error().message;
}

TEST(Pcapng, OpenCaptureRejectsWhatIsNeither) {
  const std::string text = "hello, not a capture\n";
  const std::vector<std::uint8_t> t(text.begin(), text.end());
  io::MemorySource src(t);
  RecordError err;
  EXPECT_EQ(openCapture(src, false, err), nullptr);
  EXPECT_EQ(err.kind, RecordError::Kind::notPcap);
  EXPECT_NE(err.message.find("not a pcap file"), std::string::npos) << err.message;
}

TEST(Pcapng, EditcapConversionOfSkyigPcapReadsTheSame) {
  if (std::system("command -v editcap >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "editcap (Debian package tshark/wireshark-common) not installed: check skipped";
  const std::string classic = test::tempPath("pcapng_in.pcap"), ng = test::tempPath("pcapng_out.pcapng");
  std::vector<std::vector<std::uint8_t>> payloads;
  {
    io::FileSink sink;
    ASSERT_TRUE(sink.open(classic));
    WriterOptions opt;
    opt.precision = Precision::nano;
    Writer w(sink, opt);
    ASSERT_TRUE(w.open());
    for (int i = 0; i < 5; ++i) {
      payloads.push_back(std::vector<std::uint8_t>(10 + static_cast<std::size_t>(i), static_cast<std::uint8_t>(i)));
      ASSERT_TRUE(w.writeUdp(1700000000123456789LL + i, {{10, 0, 0, 1}, 8005}, {{10, 0, 0, 2}, 8004}, payloads.back()));
    }
  }
  ASSERT_EQ(std::system(("editcap -F pcapng " + classic + " " + ng + " >/dev/null 2>&1").c_str()), 0);
  io::FileSource src;
  ASSERT_TRUE(src.open(ng));
  RecordError err;
  auto r = openCapture(src, false, err);
  ASSERT_NE(r, nullptr) << err.message;
  ASSERT_NE(dynamic_cast<PcapngReader*>(r.get()), nullptr);
  Record rec;
  for (int i = 0; i < 5; ++i) {
    ASSERT_EQ(r->next(rec), CaptureReader::Status::record) << r->error().message;
    EXPECT_EQ(rec.timestampNs, 1700000000123456789LL + i);  // editcap keeps nanoseconds (if_tsresol 9)
    UdpDatagram d;
    ASSERT_EQ(parseUdpFrame(rec.linkType, rec.data, d), FrameError::none);
    EXPECT_EQ(std::vector<std::uint8_t>(d.payload.begin(), d.payload.end()), payloads[static_cast<std::size_t>(i)]);
  }
  EXPECT_EQ(r->next(rec), CaptureReader::Status::end);
  std::filesystem::remove(classic);
  std::filesystem::remove(ng);
}

}  // namespace
}  // namespace skyig::protocol::pcap

#include "protocol/recording_format.h"

namespace skyig::protocol {
namespace {

RecordingFormat detect(const std::vector<std::uint8_t>& bytes, std::string* why = nullptr) {
  io::MemorySource src(bytes);
  return detectRecordingFormat(src, why);
}

TEST(RecordingFormat, DetectsEachFormatByItsFirstBytes) {
  EXPECT_EQ(detect(test::hexBytes("D4 C3 B2 A1 02 00 04 00")), RecordingFormat::pcap);
  EXPECT_EQ(detect(test::hexBytes("A1 B2 3C 4D 00 02 00 04")), RecordingFormat::pcap);
  EXPECT_EQ(detect(test::hexBytes("0A 0D 0D 0A 1C 00 00 00")), RecordingFormat::pcapng);
  const std::string log = "\n(1700000000.000000) can0 137#0A02000040800000\n";
  EXPECT_EQ(detect({log.begin(), log.end()}), RecordingFormat::candump);
  std::string why;
  EXPECT_EQ(detect(test::hexBytes("7F 45 4C 46 02 01"), &why), RecordingFormat::unknown);
  EXPECT_EQ(why, "first bytes 7F 45 4C 46");
  EXPECT_EQ(detect({}, &why), RecordingFormat::unknown);
  EXPECT_EQ(why, "empty file");
}

}  // namespace
}  // namespace skyig::protocol
