#include "protocol/cigi/encoder.h"

#include <cstring>
#include <type_traits>

#include "protocol/cigi/layouts.h"
#include "protocol/cigi/layouts4.h"

namespace skyig::protocol::cigi {

namespace {

// The packing side of detail::layout(): stores every field at its offset. The packet
// buffer starts zeroed, so reserved bytes are zero and bit fields are OR-ed in.
class Packer {
 public:
  Packer(std::uint8_t* p, ByteOrder order, const char* packet) : p_(p), order_(order), packet_(packet) {}

  void u8(std::size_t off, std::uint8_t v) { p_[off] = v; }
  void i8(std::size_t off, std::int8_t v) { p_[off] = static_cast<std::uint8_t>(v); }
  void u16(std::size_t off, std::uint16_t v) { storeU16(p_ + off, v, order_); }
  void u32(std::size_t off, std::uint32_t v) { storeU32(p_ + off, v, order_); }
  void f32(std::size_t off, float v) { storeF32(p_ + off, v, order_); }
  void f64(std::size_t off, double v) { storeF64(p_ + off, v, order_); }
  void constantU8(std::size_t off, std::uint8_t v) { p_[off] = v; }
  void constantU16(std::size_t off, std::uint16_t v) { storeU16(p_ + off, v, order_); }
  void constantBits(std::size_t off, unsigned shift, unsigned width, unsigned v) {
    put(off, shift, width, v);
  }

  template <class T>
  void bits(std::size_t off, unsigned shift, unsigned width, T v, const char* field) {
    const auto raw = static_cast<unsigned>(v);
    if (raw >= (1u << width) && error_.empty())
      error_ = std::string(packet_) + ": " + field + " = " + std::to_string(raw) + " does not fit in " +
               std::to_string(width) + " bit" + (width == 1 ? "" : "s");
    put(off, shift, width, raw);
  }

  const std::string& error() const { return error_; }

 private:
  void put(std::size_t off, unsigned shift, unsigned width, unsigned v) {
    const unsigned mask = (1u << width) - 1u;
    p_[off] = static_cast<std::uint8_t>(p_[off] | ((v & mask) << shift));
  }

  std::uint8_t* p_;
  ByteOrder order_;
  const char* packet_;
  std::string error_;
};

}  // namespace

std::string appendPacket(std::vector<std::uint8_t>& out, const Packet& packet, ByteOrder order) {
  const PacketId id = packetId(packet);
  const std::uint8_t size = packetSize(id);
  const std::size_t start = out.size();
  out.resize(start + size, 0);
  std::uint8_t* p = out.data() + start;
  p[0] = static_cast<std::uint8_t>(id);
  p[1] = size;
  Packer packer(p, order, packetName(id));
  std::visit([&](const auto& m) { detail::layout(packer, m); }, packet);
  if (!packer.error().empty()) {
    out.resize(start);
    return packer.error();
  }
  return {};
}

namespace {

template <class Append>
std::string encodeWith(Append append, std::span<const Packet> packets, ByteOrder order, std::vector<std::uint8_t>& out) {
  out.clear();
  if (packets.empty()) return "a CIGI message needs at least an IG Control or Start of Frame packet";
  const PacketId first = packetId(packets.front());
  if (first != PacketId::igControl && first != PacketId::startOfFrame)
    return std::string("a CIGI message must begin with IG Control or Start of Frame, not ") + packetName(first);
  for (std::size_t i = 0; i < packets.size(); ++i) {
    std::string err = append(out, packets[i], order);
    if (!err.empty()) {
      out.clear();
      return "packet " + std::to_string(i) + ": " + err;
    }
    if (out.size() > kMaxMessageSize) {
      const std::size_t n = out.size();
      out.clear();
      return "message of " + std::to_string(n) + " bytes exceeds the UDP limit of " +
             std::to_string(kMaxMessageSize) + " bytes";
    }
  }
  return {};
}

}  // namespace

std::string encodeMessage(std::span<const Packet> packets, ByteOrder order, std::vector<std::uint8_t>& out) {
  return encodeWith([](auto& o, const Packet& p, ByteOrder b) { return appendPacket(o, p, b); }, packets, order, out);
}

std::string appendPacket4(std::vector<std::uint8_t>& out, const Packet& packet, ByteOrder order) {
  const std::size_t index = packet.index();
  const std::uint16_t size = packetSize4(index);
  if (size == 0)
    return std::string(packetName(index)) + ": not in skyig's CIGI 4.0 subset (IG Control, Entity Position "
           "Control, Celestial Sphere Control, Atmosphere Control, View Control, View Definition, Sensor Control, Start of Frame)";
  const std::size_t start = out.size();
  out.resize(start + size, 0);
  std::uint8_t* p = out.data() + start;
  storeU16(p, size, order);
  storeU16(p + 2, packetId4(index), order);
  Packer packer(p, order, packetName4(packetId4(index)));
  std::visit(
      [&](const auto& m) {
        if constexpr (requires { detail::layout4(packer, m); }) detail::layout4(packer, m);
      },
      packet);
  if (!packer.error().empty()) {
    out.resize(start);
    return packer.error();
  }
  return {};
}

std::string encodeMessage4(std::span<const Packet> packets, ByteOrder order, std::vector<std::uint8_t>& out) {
  return encodeWith([](auto& o, const Packet& p, ByteOrder b) { return appendPacket4(o, p, b); }, packets, order, out);
}

}  // namespace skyig::protocol::cigi
