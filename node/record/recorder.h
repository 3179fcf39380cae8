#pragma once
// Recording what the host sends, unchanged, with arrival times: UDP datagrams to pcap
// (Wireshark, tcpdump), CAN frames to candump logs (can-utils' canplayer).
//
// Flush policy: every record goes to the kernel in one write(2) as it arrives, so a crash of
// skyig loses nothing already received; fdatasync(2) runs at most once a second, so a power
// loss loses at most the last second. A write that fails (a full disk) is cut back to the last
// complete record and stops the recording with an error; the node keeps rendering.
#include "protocol/canaerospace/can_frame.h"
#include "protocol/candump/candump.h"
#include "protocol/io/byte_sink.h"
#include "protocol/pcap/pcap_writer.h"
#include "node/transport/cigi_receiver.h"
#include "node/transport/udp_socket.h"

#include <chrono>
#include <memory>
#include <string>

namespace skyig::services {

// A file written record by record: one write(2) each, fdatasync at most once a second.
class DurableFileSink final : public protocol::io::ByteSink {
 public:
  explicit DurableFileSink(const std::string& path);  // throws std::runtime_error naming the path
  ~DurableFileSink() override;
  bool write(std::span<const std::uint8_t> bytes) override;
  bool sync() override;
  std::string error() const override { return error_; }

 private:
  int fd_ = -1;
  std::string path_;
  std::string error_;
  std::uint64_t complete_ = 0;  // bytes of complete records
  std::chrono::steady_clock::time_point lastSync_{};
};

class PcapRecorder final : public DatagramRecorder {
 public:
  // `local`: the address the datagrams were received on (the destination in the capture).
  // Throws std::runtime_error when the file cannot be created.
  PcapRecorder(const std::string& path, const Endpoint& local);
  bool record(std::span<const std::uint8_t> datagram, const Sender& from, std::int64_t unixTimeNs) override;
  std::string error() const override;
  std::uint64_t records() const { return writer_.records(); }

 private:
  DurableFileSink sink_;
  protocol::pcap::Writer writer_;
  protocol::pcap::Endpoint local_;
  bool headerWritten_ = false;
};

class CandumpRecorder {
 public:
  CandumpRecorder(const std::string& path, std::string interface);
  bool record(const protocol::canaerospace::CanFrame& frame, std::int64_t unixTimeNs);
  std::string error() const;

 private:
  DurableFileSink sink_;
  protocol::candump::Writer writer_;
  std::string interface_;
};

protocol::pcap::Endpoint toPcapEndpoint(const Sender& a);

}  // namespace skyig::services
