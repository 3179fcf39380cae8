// pcap: byte-exact file and record headers, Ethernet/IPv4/UDP wrapping with correct
// checksums, round trips in both byte orders and precisions, and corrupt or truncated files
// rejected naming the record and byte offset, with --skip-bad style resynchronisation.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "protocol/io/byte_sink.h"
#include "protocol/io/byte_source.h"
#include "protocol/pcap/pcap_reader.h"
#include "protocol/pcap/pcap_writer.h"
#include "tests/protocol/hex.h"
#include "tests/protocol/temp_path.h"

namespace skyig::protocol::pcap {
namespace {

using test::hexBytes;
using test::toHex;

const Endpoint kHost{{10, 0, 0, 1}, 8005};
const Endpoint kIg{{10, 0, 0, 2}, 8004};

std::vector<std::uint8_t> payload(std::size_t n, std::uint8_t seed) {
  std::vector<std::uint8_t> p(n);
  for (std::size_t i = 0; i < n; ++i) p[i] = static_cast<std::uint8_t>(seed + i * 7);
  return p;
}

// A file of `n` records, 100 ms apart from 1700000000 s.
std::vector<std::uint8_t> makeFile(int n, WriterOptions opt = {}) {
  io::MemorySink sink;
  Writer w(sink, opt);
  EXPECT_TRUE(w.open()) << w.error();
  for (int i = 0; i < n; ++i)
    EXPECT_TRUE(w.writeUdp(1700000000LL * 1000000000LL + i * 100000000LL + 123456789, kHost, kIg,
                           payload(40 + static_cast<std::size_t>(i), static_cast<std::uint8_t>(i))))
        << w.error();
  return sink.data;
}

TEST(Pcap, FileAndRecordHeadersAreByteExact) {
  io::MemorySink sink;
  WriterOptions opt;
  opt.byteOrder = ByteOrder::big;
  opt.linkType = kLinkRaw;
  Writer w(sink, opt);
  ASSERT_TRUE(w.open());
  // magic A1B2C3D4, version 2.4, thiszone 0, sigfigs 0, snaplen 262144 (libpcap's default:
  // any UDP datagram fits), link type 101.
  EXPECT_EQ(toHex(sink.data), toHex(hexBytes("A1 B2 C3 D4 00 02 00 04 | 00 00 00 00 00 00 00 00 |"
                                             "00 04 00 00 00 00 00 65")));
  const std::vector<std::uint8_t> frame{0xDE, 0xAD, 0xBE, 0xEF};
  ASSERT_TRUE(w.writeRecord(1700000000LL * 1000000000LL + 123456789, frame));
  // 1700000000 = 0x6553F100; 123456789 ns -> 123456 us = 0x0001E240; lengths 4 and 4.
  const std::vector<std::uint8_t> rec(sink.data.begin() + 24, sink.data.end());
  EXPECT_EQ(toHex(rec), toHex(hexBytes("65 53 F1 00 00 01 E2 40 | 00 00 00 04 00 00 00 04 | DE AD BE EF")));
}

TEST(Pcap, LittleEndianNanosecondHeader) {
  io::MemorySink sink;
  WriterOptions opt;
  opt.byteOrder = ByteOrder::little;
  opt.precision = Precision::nano;
  Writer w(sink, opt);
  ASSERT_TRUE(w.open());
  EXPECT_EQ(toHex(sink.data), toHex(hexBytes("4D 3C B2 A1 02 00 04 00 | 00 00 00 00 00 00 00 00 |"
                                             "00 00 04 00 01 00 00 00")));
}

TEST(Pcap, UdpFrameHeadersAndChecksums) {
  std::vector<std::uint8_t> f;
  const std::vector<std::uint8_t> p{0x01, 0x02, 0x03, 0x04};
  ASSERT_EQ(buildUdpFrame(kLinkIpv4, kHost, kIg, p, 0x1234, f), "");
  // IPv4: 45 00, total 32, id 1234, DF, TTL 64, UDP, checksum, 10.0.0.1 -> 10.0.0.2.
  // Header checksum: one's complement of 4500+0020+1234+4000+4011+0A00+0001+0A00+0002
  // = 0xEB68 -> ~ = 0x1497.
  // UDP: 8005 (1F45) -> 8004 (1F44), length 12; checksum over the pseudo-header
  // 0A00+0001+0A00+0002+0011+000C = 0x1420 and 1F45+1F44+000C+0102+0304 = 0x429B:
  // 0x56BB -> ~ = 0xA944.
  EXPECT_EQ(toHex(f), toHex(hexBytes("45 00 00 20 12 34 40 00 | 40 11 14 97 0A 00 00 01 |"
                                     "0A 00 00 02 1F 45 1F 44 | 00 0C A9 44 01 02 03 04")));
  UdpDatagram d;
  ASSERT_EQ(parseUdpFrame(kLinkIpv4, f, d), FrameError::none);
  EXPECT_EQ(d.source, kHost);
  EXPECT_EQ(d.destination, kIg);
  EXPECT_EQ(std::vector<std::uint8_t>(d.payload.begin(), d.payload.end()), p);
  EXPECT_EQ(toString(d.destination), "10.0.0.2:8004");
}

TEST(Pcap, ParsesOtherLinkTypesAndRejectsNonUdp) {
  std::vector<std::uint8_t> ip;
  const std::vector<std::uint8_t> p{9, 9};
  ASSERT_EQ(buildUdpFrame(kLinkRaw, kHost, kIg, p, 1, ip), "");
  UdpDatagram d;
  // Ethernet with an 802.1Q tag.
  std::vector<std::uint8_t> eth = hexBytes("02 00 00 00 00 02 02 00 00 00 00 01 81 00 00 05 08 00");
  eth.insert(eth.end(), ip.begin(), ip.end());
  EXPECT_EQ(parseUdpFrame(kLinkEthernet, eth, d), FrameError::none);
  EXPECT_EQ(d.payload.size(), 2u);
  // Linux cooked v1 (protocol at 14) and v2 (protocol at 0).
  std::vector<std::uint8_t> sll(16, 0);
  sll[14] = 0x08;
  sll.insert(sll.end(), ip.begin(), ip.end());
  EXPECT_EQ(parseUdpFrame(kLinkLinuxSll, sll, d), FrameError::none);
  std::vector<std::uint8_t> sll2(20, 0);
  sll2[0] = 0x08;
  sll2.insert(sll2.end(), ip.begin(), ip.end());
  EXPECT_EQ(parseUdpFrame(kLinkLinuxSll2, sll2, d), FrameError::none);
  // BSD loopback, AF_INET = 2 little-endian.
  std::vector<std::uint8_t> null{2, 0, 0, 0};
  null.insert(null.end(), ip.begin(), ip.end());
  EXPECT_EQ(parseUdpFrame(kLinkNull, null, d), FrameError::none);

  auto tcp = ip;
  tcp[9] = 6;
  EXPECT_EQ(parseUdpFrame(kLinkRaw, tcp, d), FrameError::notUdp);
  auto frag = ip;
  frag[6] = 0x20;  // more fragments
  EXPECT_EQ(parseUdpFrame(kLinkRaw, frag, d), FrameError::fragmented);
  auto v6 = ip;
  v6[0] = 0x60;
  EXPECT_EQ(parseUdpFrame(kLinkRaw, v6, d), FrameError::notIpv4);
  EXPECT_EQ(parseUdpFrame(kLinkRaw, std::span(ip.data(), 25), d), FrameError::truncated);
  auto badLen = ip;
  badLen[20 + 5] = 200;  // UDP length beyond the IP payload
  EXPECT_EQ(parseUdpFrame(kLinkRaw, badLen, d), FrameError::badUdpLength);
  EXPECT_EQ(parseUdpFrame(147, ip, d), FrameError::unsupportedLinkType);
}

TEST(Pcap, RoundTripInBothByteOrdersAndPrecisions) {
  for (ByteOrder order : {ByteOrder::big, ByteOrder::little})
    for (Precision prec : {Precision::micro, Precision::nano}) {
      WriterOptions opt;
      opt.byteOrder = order;
      opt.precision = prec;
      const auto file = makeFile(5, opt);
      io::MemorySource src(file);
      Reader r(src);
      ASSERT_TRUE(r.open()) << r.error().message;
      EXPECT_EQ(r.header().byteOrder, order);
      EXPECT_EQ(r.header().precision, prec);
      EXPECT_EQ(r.header().linkType, kLinkEthernet);
      Record rec;
      for (int i = 0; i < 5; ++i) {
        ASSERT_EQ(r.next(rec), Reader::Status::record) << r.error().message;
        EXPECT_EQ(rec.number, static_cast<std::uint64_t>(i + 1));
        const std::int64_t exact = 1700000000LL * 1000000000LL + i * 100000000LL + 123456789;
        EXPECT_EQ(rec.timestampNs, prec == Precision::nano ? exact : exact - 789);
        UdpDatagram d;
        ASSERT_EQ(parseUdpFrame(r.header().linkType, rec.data, d), FrameError::none);
        EXPECT_EQ(std::vector<std::uint8_t>(d.payload.begin(), d.payload.end()),
                  payload(40 + static_cast<std::size_t>(i), static_cast<std::uint8_t>(i)));
        EXPECT_EQ(d.destination.port, 8004);
      }
      EXPECT_EQ(r.next(rec), Reader::Status::end);
    }
}

TEST(Pcap, NotAPcapFile) {
  const std::vector<std::uint8_t> empty;
  io::MemorySource s0(empty);
  Reader r0(s0);
  EXPECT_FALSE(r0.open());
  EXPECT_EQ(r0.error().kind, RecordError::Kind::notPcap);
  EXPECT_NE(r0.error().message.find("empty"), std::string::npos);

  const auto pcapng = hexBytes("0A 0D 0D 0A 1C 00 00 00 4D 3C 2B 1A 01 00 00 00 FF FF FF FF FF FF FF FF");
  io::MemorySource s1(pcapng);
  Reader r1(s1);
  EXPECT_FALSE(r1.open());
  EXPECT_NE(r1.error().message.find("pcapng"), std::string::npos) << r1.error().message;

  const std::string text = "(1700000000.000000) can0 137#0A02000040800000\n";
  const std::vector<std::uint8_t> t(text.begin(), text.end());
  io::MemorySource s2(t);
  Reader r2(s2);
  EXPECT_FALSE(r2.open());
  EXPECT_NE(r2.error().message.find("magic 28 31 37 30 at byte 0"), std::string::npos) << r2.error().message;
  EXPECT_NE(r2.error().message.find("candump"), std::string::npos) << r2.error().message;

  auto file = makeFile(1);
  file.resize(20);
  io::MemorySource s3(file);
  Reader r3(s3);
  EXPECT_FALSE(r3.open());
  EXPECT_EQ(r3.error().kind, RecordError::Kind::truncatedHeader);

  file = makeFile(1);
  file[4] = 3;  // version 3.4 (little-endian writer on x86)
  file[5] = 0;
  io::MemorySource s4(file);
  Reader r4(s4);
  EXPECT_FALSE(r4.open());
  EXPECT_EQ(r4.error().kind, RecordError::Kind::unsupportedVersion);
}

TEST(Pcap, TruncatedLastRecordNamesRecordAndOffset) {
  auto file = makeFile(3, WriterOptions{kLinkEthernet, Precision::micro, ByteOrder::little, 65535, 0});
  // Records: 16 + 42 + 40+i bytes; record 3 starts at 24 + 98 + 99 = 221.
  file.resize(file.size() - 5);  // as a crash in the middle of writing record 3 would leave
  io::MemorySource src(file);
  Reader r(src);
  ASSERT_TRUE(r.open());
  Record rec;
  ASSERT_EQ(r.next(rec), Reader::Status::record);
  ASSERT_EQ(r.next(rec), Reader::Status::record);
  EXPECT_EQ(rec.offset, 24u + 98u);
  ASSERT_EQ(r.next(rec), Reader::Status::error);
  EXPECT_EQ(r.error().kind, RecordError::Kind::truncatedRecord);
  EXPECT_EQ(r.error().record, 3u);
  EXPECT_EQ(r.error().offset, 221u);
  EXPECT_NE(r.error().message.find("record 3 at byte 221 claims 84 bytes but the file ends 79 bytes after its header"),
            std::string::npos)
      << r.error().message;
  EXPECT_EQ(r.next(rec), Reader::Status::error);  // stays failed

  // A cut inside a record header.
  file.resize(221 + 7);
  io::MemorySource src2(file);
  Reader r2(src2);
  ASSERT_TRUE(r2.open());
  r2.next(rec);
  r2.next(rec);
  ASSERT_EQ(r2.next(rec), Reader::Status::error);
  EXPECT_EQ(r2.error().kind, RecordError::Kind::truncatedRecordHeader);
  EXPECT_NE(r2.error().message.find("7 of 16 header bytes"), std::string::npos) << r2.error().message;

  // With skipBad the truncated tail is counted and the good records are kept.
  io::MemorySource src3(file);
  Reader r3(src3, true);
  ASSERT_TRUE(r3.open());
  int good = 0;
  while (r3.next(rec) == Reader::Status::record) ++good;
  EXPECT_EQ(good, 2);
  EXPECT_EQ(r3.skipped(), 1u);
}

TEST(Pcap, CorruptRecordInTheMiddleIsSkippedAndReadingResumes) {
  auto file = makeFile(10, WriterOptions{kLinkEthernet, Precision::micro, ByteOrder::little, 65535, 0});
  // Record 4 header at 24 + 3 records (98, 99, 100) = 321: captured length 0x7FFFFFFF.
  const std::size_t rec4 = 24 + 98 + 99 + 100;
  file[rec4 + 8] = 0xFF;
  file[rec4 + 9] = 0xFF;
  file[rec4 + 10] = 0xFF;
  file[rec4 + 11] = 0x7F;
  {
    io::MemorySource src(file);
    Reader r(src);
    ASSERT_TRUE(r.open());
    Record rec;
    for (int i = 0; i < 3; ++i) ASSERT_EQ(r.next(rec), Reader::Status::record);
    ASSERT_EQ(r.next(rec), Reader::Status::error);
    EXPECT_EQ(r.error().kind, RecordError::Kind::recordTooLong);
    EXPECT_EQ(r.error().record, 4u);
    EXPECT_EQ(r.error().offset, rec4);
    EXPECT_NE(r.error().message.find("record 4 at byte 321"), std::string::npos) << r.error().message;
    EXPECT_NE(r.error().message.find("2147483647"), std::string::npos) << r.error().message;
  }
  io::MemorySource src(file);
  Reader r(src, true);
  ASSERT_TRUE(r.open());
  Record rec;
  std::vector<std::uint64_t> payloadSizes;
  while (r.next(rec) == Reader::Status::record) {
    UdpDatagram d;
    ASSERT_EQ(parseUdpFrame(kLinkEthernet, rec.data, d), FrameError::none);
    payloadSizes.push_back(d.payload.size());
  }
  EXPECT_EQ(r.skipped(), 1u);
  ASSERT_EQ(r.skippedErrors().size(), 1u);
  EXPECT_EQ(r.skippedErrors()[0].record, 4u);
  // Records 1-3 and 5-10 survive: payloads of 40+i bytes.
  EXPECT_EQ(payloadSizes, (std::vector<std::uint64_t>{40, 41, 42, 44, 45, 46, 47, 48, 49}));
}

TEST(Pcap, FilesOnDiskAndAFullDisk) {
  const std::string path = test::tempPath("pcap_test.pcap");
  {
    io::FileSink sink;
    ASSERT_TRUE(sink.open(path)) << sink.error();
    Writer w(sink);
    ASSERT_TRUE(w.open());
    const auto p = payload(88, 1);
    ASSERT_TRUE(w.writeUdp(5'000'000'000, kHost, kIg, p));
    // Unbuffered: the record is in the file before the writer is gone (crash safety).
    EXPECT_EQ(std::filesystem::file_size(path), 24u + 16u + 14u + 20u + 8u + 88u);
  }
  io::FileSource src;
  ASSERT_TRUE(src.open(path)) << src.error();
  Reader r(src);
  ASSERT_TRUE(r.open());
  Record rec;
  ASSERT_EQ(r.next(rec), Reader::Status::record);
  EXPECT_EQ(rec.timestampNs, 5'000'000'000);
  EXPECT_EQ(r.next(rec), Reader::Status::end);
  std::filesystem::remove(path);

  io::FileSource missing;
  EXPECT_FALSE(missing.open("/nonexistent/x.pcap"));
  EXPECT_NE(missing.error().find("/nonexistent/x.pcap: No such file"), std::string::npos) << missing.error();

  // /dev/full fails every write with ENOSPC, as a full disk does.
  if (std::filesystem::exists("/dev/full")) {
    io::FileSink full;
    ASSERT_TRUE(full.open("/dev/full"));
    Writer w(full);
    EXPECT_FALSE(w.open());
    EXPECT_NE(w.error().find("No space left on device"), std::string::npos) << w.error();
    EXPECT_FALSE(w.writeUdp(0, kHost, kIg, payload(8, 0)));
  }
}

TEST(Pcap, WriterRejectsBadInput) {
  io::MemorySink sink;
  Writer w(sink);
  ASSERT_TRUE(w.open());
  EXPECT_FALSE(w.writeRecord(-1, payload(4, 0)));
  EXPECT_NE(w.error().find("negative timestamp -1"), std::string::npos) << w.error();
  Writer w3(sink, WriterOptions{kLinkLinuxSll, Precision::micro, ByteOrder::little, 65535, 0});
  EXPECT_FALSE(w3.open());
}

// A frame longer than the snap length is cut there, with its original length in the record
// header (tcpdump's behaviour), counted, and the writer goes on: never a failed recording.
TEST(Pcap, FrameBeyondTheSnapLengthIsTruncatedNotFatal) {
  io::MemorySink sink;
  Writer w(sink, WriterOptions{kLinkRaw, Precision::micro, ByteOrder::little, 100, 0});
  ASSERT_TRUE(w.open());
  EXPECT_TRUE(w.writeRecord(0, payload(101, 0)));
  EXPECT_TRUE(w.writeRecord(1000, payload(20, 0)));
  EXPECT_EQ(w.truncated(), 1u);
  EXPECT_EQ(w.records(), 2u);
  io::MemorySource source(sink.data);
  Reader r(source);
  ASSERT_TRUE(r.open());
  Record rec;
  ASSERT_EQ(r.next(rec), Reader::Status::record);
  EXPECT_EQ(rec.data.size(), 100u);
  EXPECT_EQ(rec.originalLength, 101u);
  ASSERT_EQ(r.next(rec), Reader::Status::record);
  EXPECT_EQ(rec.data.size(), 20u);
}

// The largest UDP payload IPv4 carries (65,507 bytes) in an Ethernet frame fits the default
// snap length whole.
TEST(Pcap, LargestUdpDatagramIsRecordedWhole) {
  io::MemorySink sink;
  Writer w(sink);
  ASSERT_TRUE(w.open());
  ASSERT_TRUE(w.writeUdp(0, kHost, kIg, payload(65507, 7))) << w.error();
  EXPECT_EQ(w.truncated(), 0u);
  io::MemorySource source(sink.data);
  Reader r(source);
  ASSERT_TRUE(r.open());
  Record rec;
  ASSERT_EQ(r.next(rec), Reader::Status::record);
  UdpDatagram d;
  ASSERT_EQ(parseUdpFrame(rec.linkType, rec.data, d), FrameError::none);
  EXPECT_EQ(d.payload.size(), 65507u);
}

}  // namespace
}  // namespace skyig::protocol::pcap
