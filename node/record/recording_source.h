#pragma once
// A recording read back in time order, whatever its format (pcap, pcapng, candump), as
// host events: a CIGI datagram or a CAN frame, with the recorded arrival time.
#include "protocol/canaerospace/can_frame.h"
#include "protocol/candump/candump.h"
#include "protocol/io/byte_source.h"
#include "protocol/pcap/pcap_reader.h"
#include "protocol/recording_format.h"
#include "node/host/sender.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace skyig::services {

// A recording that cannot be read: what() names the file, the record and the byte offset.
class RecordingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct HostEvent {
  enum class Kind { datagram, canFrame } kind = Kind::datagram;
  std::int64_t timeNs = 0;                    // as recorded
  std::uint64_t record = 0;                   // record (pcap) or line (candump) number
  std::vector<std::uint8_t> payload;          // the UDP payload
  Sender from{};
  std::uint16_t destinationPort = 0;
  protocol::canaerospace::CanFrame frame;
};

class RecordingSource {
 public:
  // Opens and identifies the file; throws RecordingError when it is not a recording.
  RecordingSource(const std::string& path, bool skipBad);
  // The next event, or false at the end. Throws RecordingError at a bad record unless
  // skipBad, in which case bad records are counted and passed over, and for a classic pcap
  // file of a link type skyig cannot parse (whatever skipBad: nothing in it could be read).
  bool next(HostEvent& out);
  protocol::RecordingFormat format() const { return format_; }
  std::uint64_t skipped() const;
  std::vector<std::string> skippedMessages() const;
  std::uint64_t nonUdpFrames() const { return nonUdp_; }
  // False for a FIFO or a pipe: read once, front to back (no first pass for the progress).
  bool seekable() const { return file_.seekable(); }

 private:
  std::string path_;
  protocol::io::FileSource file_;
  protocol::RecordingFormat format_;
  std::unique_ptr<protocol::pcap::CaptureReader> capture_;
  std::unique_ptr<protocol::candump::Reader> candump_;
  protocol::pcap::Record record_;
  protocol::candump::Record line_;
  std::uint64_t nonUdp_ = 0;
};

}  // namespace skyig::services
