#include "protocol/cigi/decoder.h"

#include <cstdio>
#include <type_traits>
#include <utility>

#include "protocol/cigi/layouts.h"
#include "protocol/cigi/layouts4.h"

namespace skyig::protocol::cigi {

namespace {

// The unpacking side of detail::layout(): loads every field from its offset. Constant
// fields (version, magic) are checked once per message, by decodeMessage.
class Unpacker {
 public:
  Unpacker(const std::uint8_t* p, ByteOrder order) : p_(p), order_(order) {}

  void u8(std::size_t off, std::uint8_t& v) const { v = p_[off]; }
  void i8(std::size_t off, std::int8_t& v) const { v = static_cast<std::int8_t>(p_[off]); }
  void u16(std::size_t off, std::uint16_t& v) const { v = loadU16(p_ + off, order_); }
  void u32(std::size_t off, std::uint32_t& v) const { v = loadU32(p_ + off, order_); }
  void f32(std::size_t off, float& v) const { v = loadF32(p_ + off, order_); }
  void f64(std::size_t off, double& v) const { v = loadF64(p_ + off, order_); }
  void constantU8(std::size_t, std::uint8_t) const {}
  void constantU16(std::size_t, std::uint16_t) const {}
  void constantBits(std::size_t, unsigned, unsigned, unsigned) const {}

  template <class T>
  void bits(std::size_t off, unsigned shift, unsigned width, T& v, const char*) const {
    const unsigned raw = (static_cast<unsigned>(p_[off]) >> shift) & ((1u << width) - 1u);
    if constexpr (std::is_same_v<T, bool>)
      v = raw != 0;
    else
      v = static_cast<T>(raw);
  }

 private:
  const std::uint8_t* p_;
  ByteOrder order_;
};

template <class T>
void unpackInto(std::vector<Packet>& packets, const std::uint8_t* p, ByteOrder order) {
  T m{};
  Unpacker u(p, order);
  detail::layout(u, m);
  packets.emplace_back(m);
}

// Unpacks a known packet whose size has been checked; false for ids skyig does not decode.
bool unpack(PacketId id, const std::uint8_t* p, ByteOrder order, std::vector<Packet>& packets) {
  switch (id) {
    case PacketId::igControl: unpackInto<IgControl>(packets, p, order); return true;
    case PacketId::entityControl: unpackInto<EntityControl>(packets, p, order); return true;
    case PacketId::rateControl: unpackInto<RateControl>(packets, p, order); return true;
    case PacketId::celestialSphereControl: unpackInto<CelestialSphereControl>(packets, p, order); return true;
    case PacketId::atmosphereControl: unpackInto<AtmosphereControl>(packets, p, order); return true;
    case PacketId::environmentalRegionControl:
      unpackInto<EnvironmentalRegionControl>(packets, p, order);
      return true;
    case PacketId::weatherControl: unpackInto<WeatherControl>(packets, p, order); return true;
    case PacketId::viewControl: unpackInto<ViewControl>(packets, p, order); return true;
    case PacketId::viewDefinition: unpackInto<ViewDefinition>(packets, p, order); return true;
    case PacketId::sensorControl: unpackInto<SensorControl>(packets, p, order); return true;
    case PacketId::startOfFrame: unpackInto<StartOfFrame>(packets, p, order); return true;
  }
  return false;
}

DecodeError makeError(ErrorKind kind, std::size_t offset, std::uint16_t id, std::size_t size, std::uint32_t value = 0,
                      bool cigi4 = false) {
  return DecodeError{kind, offset, id, cigi4, size, value};
}

template <class T>
void unpackInto4(std::vector<Packet>& packets, const std::uint8_t* p, ByteOrder order) {
  if constexpr (requires(Unpacker u, T m) { detail::layout4(u, m); }) {
    T m{};
    Unpacker u(p, order);
    detail::layout4(u, m);
    packets.emplace_back(m);
  }
}

// Unpacks a CIGI 4 packet of a known variant index whose size has been checked: the
// alternative with that index, through its layout4 (every index variantIndexOf4 returns
// has one).
template <std::size_t... I>
void unpack4(std::size_t index, const std::uint8_t* p, ByteOrder order, std::vector<Packet>& packets,
             std::index_sequence<I...>) {
  ((index == I ? unpackInto4<std::variant_alternative_t<I, Packet>>(packets, p, order) : void()), ...);
}

void unpack4(std::size_t index, const std::uint8_t* p, ByteOrder order, std::vector<Packet>& packets) {
  unpack4(index, p, order, packets, std::make_index_sequence<kPacketTypeCount>{});
}

// DecodeError::value of unsupportedVersion: the major version, or these for CIGI 3 minors.
constexpr std::uint32_t kVersion3Minor = 0x300;    // + minor version
constexpr std::uint32_t kVersion30or31 = 0x3FF;    // the 16-byte first packet of 3.0/3.1

// A CIGI 4 message starts with a 16-bit size (24) and a 16-bit id (0 IG Control, 0xFFFF
// Start of Frame) in either byte order (CIGI 4.0 ICD; CCL 4 CigiIncomingMsg).
bool looksLikeCigi4(std::span<const std::uint8_t> b) {
  if (b.size() < 4) return false;
  const bool size24 = (b[0] == 0 && b[1] == 24) || (b[0] == 24 && b[1] == 0);
  const bool idFirst = (b[2] == 0 && b[3] == 0) || (b[2] == 0xFF && b[3] == 0xFF);
  return size24 && idFirst;
}

// Checks the first packet and finds the byte order; nullopt-free: returns an error or sets
// out.byteOrder / out.minorVersion.
std::optional<DecodeError> readFirstPacket(std::span<const std::uint8_t> b, DecodedMessage& out) {
  if (b.empty()) return makeError(ErrorKind::emptyMessage, 0, 0, 0);
  if (b.size() < 2) return makeError(ErrorKind::truncatedHeader, 0, b[0], b.size());
  const std::uint8_t id = b[0];
  const std::uint8_t size = b[1];
  if (id != static_cast<std::uint8_t>(PacketId::igControl) && id != static_cast<std::uint8_t>(PacketId::startOfFrame))
    return makeError(ErrorKind::missingFirstPacket, 0, id, size);
  if (b.size() < 3) return makeError(ErrorKind::packetPastEnd, 0, id, size);
  const std::uint8_t major = b[2];
  if (major != kMajorVersion) return makeError(ErrorKind::unsupportedVersion, 2, id, size, major);
  // CIGI 3.0 and 3.1 used a 16-byte IG Control / Start of Frame with other field offsets.
  if (size == 16) return makeError(ErrorKind::unsupportedVersion, 0, id, size, kVersion30or31);
  if (size < 2) return makeError(ErrorKind::packetSizeTooSmall, 0, id, size);
  if (size != 24) return makeError(ErrorKind::wrongPacketSize, 0, id, size, 24);
  if (b.size() < size) return makeError(ErrorKind::packetPastEnd, 0, id, size);
  const std::uint16_t magic = loadU16(&b[6], ByteOrder::big);
  if (magic == 0x8000)
    out.byteOrder = ByteOrder::big;
  else if (magic == 0x0080)
    out.byteOrder = ByteOrder::little;
  else
    return makeError(ErrorKind::badByteSwapMagic, 6, id, size, magic);
  const std::size_t minorByte = id == static_cast<std::uint8_t>(PacketId::igControl) ? 4 : 5;
  const std::uint8_t minor = static_cast<std::uint8_t>(b[minorByte] >> 4);
  if (minor != 2 && minor != 3)
    return makeError(ErrorKind::unsupportedVersion, minorByte, id, size, kVersion3Minor + minor);
  out.minorVersion = minor;
  return std::nullopt;
}

// CIGI 4: every packet starts with u16 size, u16 id in the sender's order; the first is IG
// Control (id 0) or Start of Frame (0xFFFF), 24 bytes, so its size bytes tell the order.
void decodeMessage4(std::span<const std::uint8_t> b, DecodedMessage& out) {
  out.majorVersion = 4;
  out.byteOrder = (b[0] == 0 && b[1] == 24) ? ByteOrder::big : ByteOrder::little;
  const std::uint16_t firstId = loadU16(&b[2], out.byteOrder);
  if (b.size() < 24) {
    out.error = makeError(ErrorKind::packetPastEnd, 0, firstId, 24, 0, true);
    return;
  }
  if (b[4] != 4) {
    out.error = makeError(ErrorKind::unsupportedVersion, 4, firstId, 24, b[4], true);
    return;
  }
  out.minorVersion = static_cast<std::uint8_t>(b[7] >> 4);
  const std::size_t n = b.size();
  std::size_t off = 0;
  while (off < n) {
    if (n - off < 4) {
      out.error = makeError(ErrorKind::truncatedHeader, off, 0, n - off, 0, true);
      return;
    }
    const std::uint16_t size = loadU16(&b[off], out.byteOrder);
    const std::uint16_t id = loadU16(&b[off + 2], out.byteOrder);
    if (size < 4) {
      out.error = makeError(ErrorKind::packetSizeTooSmall, off, id, size, 0, true);
      return;
    }
    if (size > n - off) {
      out.error = makeError(ErrorKind::packetPastEnd, off, id, size, 0, true);
      return;
    }
    const std::size_t index = variantIndexOf4(id);
    if (index == kPacketTypeCount) {
      ++out.skippedPackets;
    } else if (size != packetSize4(index)) {
      out.error = makeError(ErrorKind::wrongPacketSize, off, id, size, packetSize4(index), true);
      return;
    } else {
      unpack4(index, b.data() + off, out.byteOrder, out.packets);
    }
    off += size;
  }
}

}  // namespace


const char* toString(ErrorKind k) {
  switch (k) {
    case ErrorKind::emptyMessage: return "empty message";
    case ErrorKind::truncatedHeader: return "truncated packet header";
    case ErrorKind::missingFirstPacket: return "message does not begin with IG Control or Start of Frame";
    case ErrorKind::unsupportedVersion: return "unsupported CIGI version";
    case ErrorKind::badByteSwapMagic: return "bad byte-swap magic number";
    case ErrorKind::packetSizeTooSmall: return "packet size too small";
    case ErrorKind::packetPastEnd: return "packet runs past the end of the message";
    case ErrorKind::wrongPacketSize: return "wrong packet size";
  }
  return "unknown error";
}

std::string DecodeError::describe() const {
  std::string s = std::string(toString(kind)) + " at byte " + std::to_string(offset);
  const char* name = cigi4 ? packetName4(packetId) : packetName(static_cast<PacketId>(packetId & 0xFFu));
  s += std::string(cigi4 ? " (CIGI 4 packet id " : " (packet id ") + std::to_string(packetId) + " " + name +
       ", size " + std::to_string(packetSize) + ")";
  switch (kind) {
    case ErrorKind::unsupportedVersion:
      if (value == kVersion30or31)
        s += ": CIGI 3.0 or 3.1 (16-byte first packet)";
      else if (value >= kVersion3Minor && value < kVersion3Minor + 16)
        s += ": CIGI 3." + std::to_string(value - kVersion3Minor);
      else
        s += ": major version " + std::to_string(value);
      s += "; skyig speaks CIGI 3.2, 3.3 and 4.0";
      break;
    case ErrorKind::badByteSwapMagic: {
      char buf[48];
      std::snprintf(buf, sizeof buf, ": 0x%04X, expected 80 00 or 00 80", static_cast<unsigned>(value));
      s += buf;
      break;
    }
    case ErrorKind::wrongPacketSize: s += ": expected " + std::to_string(value) + " bytes"; break;
    default: break;
  }
  return s;
}

void decodeMessage(std::span<const std::uint8_t> bytes, DecodedMessage& out) {
  out.packets.clear();
  out.skippedPackets = 0;
  out.error.reset();
  out.byteOrder = ByteOrder::big;
  out.majorVersion = 0;
  out.minorVersion = 0;
  if (looksLikeCigi4(bytes)) {
    decodeMessage4(bytes, out);
    return;
  }
  out.majorVersion = 3;
  if (auto err = readFirstPacket(bytes, out)) {
    out.error = err;
    return;
  }
  const std::size_t n = bytes.size();
  std::size_t off = 0;
  while (off < n) {
    if (n - off < 2) {
      out.error = makeError(ErrorKind::truncatedHeader, off, bytes[off], n - off);
      return;
    }
    const std::uint8_t id = bytes[off];
    const std::uint8_t size = bytes[off + 1];
    if (size < 2) {
      out.error = makeError(ErrorKind::packetSizeTooSmall, off, id, size);
      return;
    }
    if (size > n - off) {
      out.error = makeError(ErrorKind::packetPastEnd, off, id, size);
      return;
    }
    const std::uint8_t expected = packetSize(static_cast<PacketId>(id));
    if (expected == 0) {
      ++out.skippedPackets;
    } else if (size != expected) {
      out.error = makeError(ErrorKind::wrongPacketSize, off, id, size, expected);
      return;
    } else {
      unpack(static_cast<PacketId>(id), bytes.data() + off, out.byteOrder, out.packets);
    }
    off += size;
  }
}

DecodedMessage decodeMessage(std::span<const std::uint8_t> bytes) {
  DecodedMessage m;
  decodeMessage(bytes, m);
  return m;
}

}  // namespace skyig::protocol::cigi
