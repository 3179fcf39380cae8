#include "node/record/recording_source.h"

#include "protocol/pcap/pcapng_reader.h"
#include "protocol/pcap/udp_frame.h"

#include <cstring>

namespace skyig::services {

namespace pcap = protocol::pcap;

RecordingSource::RecordingSource(const std::string& path, bool skipBad) : path_(path) {
  if (!file_.open(path)) throw RecordingError(path + ": " + file_.error());
  std::string seen;
  format_ = protocol::detectRecordingFormat(file_, &seen);
  switch (format_) {
    case protocol::RecordingFormat::pcap:
    case protocol::RecordingFormat::pcapng: {
      pcap::RecordError error;
      capture_ = pcap::openCapture(file_, skipBad, error);
      if (!capture_) throw RecordingError(path + ": " + error.message);
      break;
    }
    case protocol::RecordingFormat::candump:
      candump_ = std::make_unique<protocol::candump::Reader>(file_, skipBad);
      break;
    default:
      throw RecordingError(path + ": not a recording (pcap, pcapng or candump log expected; " + seen + ")");
  }
}

bool RecordingSource::next(HostEvent& out) {
  if (candump_) {
    const auto status = candump_->next(line_);
    if (status == protocol::candump::Reader::Status::end) return false;
    if (status == protocol::candump::Reader::Status::error) throw RecordingError(path_ + ": " + candump_->error().message);
    out.kind = HostEvent::Kind::canFrame;
    out.timeNs = line_.timestampUs * 1000;
    out.record = line_.line;
    out.frame = line_.frame;
    return true;
  }
  for (;;) {
    const auto status = capture_->next(record_);
    if (status == pcap::CaptureReader::Status::end) return false;
    if (status == pcap::CaptureReader::Status::error) throw RecordingError(path_ + ": " + capture_->error().message);
    pcap::UdpDatagram d;
    const pcap::FrameError frameError = pcap::parseUdpFrame(record_.linkType, record_.data, d);
    // One link type for the whole classic file: not one record of it could be read. (A pcapng
    // file may hold other interfaces beside the host's: their records are passed over.)
    if (frameError == pcap::FrameError::unsupportedLinkType && format_ == protocol::RecordingFormat::pcap)
      throw RecordingError(path_ + ": pcap link type " + std::to_string(record_.linkType) +
                           " is not supported: skyig reads NULL (0), ETHERNET (1), RAW (101), LINUX_SLL (113), "
                           "IPV4 (228) and LINUX_SLL2 (276) captures");
    if (frameError != pcap::FrameError::none) {
      ++nonUdp_;  // ARP, TCP and the like in a Wireshark capture: not the host's
      continue;
    }
    out.kind = HostEvent::Kind::datagram;
    out.timeNs = record_.timestampNs;
    out.record = record_.number;
    out.payload.assign(d.payload.begin(), d.payload.end());
    out.from = Sender{};
    for (const std::uint8_t byte : d.source.ip) out.from.address = (out.from.address << 8) | byte;  // network order
    out.from.port = d.source.port;
    out.destinationPort = d.destination.port;
    return true;
  }
}

std::uint64_t RecordingSource::skipped() const { return candump_ ? candump_->skipped() : capture_->skipped(); }

std::vector<std::string> RecordingSource::skippedMessages() const {
  std::vector<std::string> m;
  if (candump_)
    for (const auto& e : candump_->skippedErrors()) m.push_back(e.message);
  else
    for (const auto& e : capture_->skippedErrors()) m.push_back(e.message);
  return m;
}

}  // namespace skyig::services
