#include "node/record/recorder.h"

#include "render/output_file.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace skyig::services {

DurableFileSink::DurableFileSink(const std::string& path) : path_(path) {
  // Written as it goes, in place: "-" is stdout, a FIFO stays one (render/output_file.h).
  fd_ = render::openOutputStream(path);
  lastSync_ = std::chrono::steady_clock::now();
}

DurableFileSink::~DurableFileSink() {
  if (fd_ >= 0) {
    ::fdatasync(fd_);
    ::close(fd_);
  }
}

bool DurableFileSink::write(std::span<const std::uint8_t> bytes) {
  if (fd_ < 0) return false;
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      error_ = path_ + ": " + std::strerror(n < 0 ? errno : ENOSPC);
      // Keep the file a sequence of whole records: drop the partial one.
      if (::ftruncate(fd_, static_cast<off_t>(complete_)) != 0) error_ += " (and could not trim the partial record)";
      ::close(fd_);
      fd_ = -1;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  complete_ += bytes.size();
  const auto now = std::chrono::steady_clock::now();
  if (now - lastSync_ >= std::chrono::seconds(1)) {
    lastSync_ = now;
    return sync();
  }
  return true;
}

bool DurableFileSink::sync() {
  if (fd_ < 0) return false;
  if (::fdatasync(fd_) != 0 && errno != EINVAL) {  // EINVAL: a file that cannot be synced (a pipe)
    error_ = path_ + ": fdatasync: " + std::strerror(errno);
    return false;
  }
  return true;
}

protocol::pcap::Endpoint toPcapEndpoint(const Sender& a) {
  protocol::pcap::Endpoint e;
  for (std::size_t i = 0; i < 4; ++i)  // the array holds the address in network (big-endian) order
    e.ip[i] = static_cast<std::uint8_t>(a.address >> (24 - 8 * i));
  e.port = a.port;
  return e;
}

PcapRecorder::PcapRecorder(const std::string& path, const Endpoint& local)
    : sink_(path), writer_(sink_, protocol::pcap::WriterOptions{}), local_(toPcapEndpoint(toSender(toSockaddr(local)))) {
  // A file that cannot take even its header (a full disk) fails at the first record, like
  // any later write: the recording stops, the node does not.
  headerWritten_ = writer_.open();
}

bool PcapRecorder::record(std::span<const std::uint8_t> datagram, const Sender& from, std::int64_t unixTimeNs) {
  return headerWritten_ && writer_.writeUdp(unixTimeNs, toPcapEndpoint(from), local_, datagram);
}

std::string PcapRecorder::error() const { return writer_.error(); }

CandumpRecorder::CandumpRecorder(const std::string& path, std::string interface)
    : sink_(path), writer_(sink_), interface_(std::move(interface)) {}

bool CandumpRecorder::record(const protocol::canaerospace::CanFrame& frame, std::int64_t unixTimeNs) {
  return writer_.write(unixTimeNs / 1000, interface_, frame);
}

std::string CandumpRecorder::error() const { return writer_.error(); }

}  // namespace skyig::services
