#pragma once
// Loads and stores of fixed-width fields in an explicit byte order. CIGI 3 packets are in the
// sender's native order (announced by the 0x8000 magic), CANaerospace and network headers are
// big-endian and pcap headers are in the writer's order, so every access names its order and
// nothing depends on the byte order of the machine running skyig.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace skyig::protocol {

enum class ByteOrder : std::uint8_t { big, little };

constexpr ByteOrder nativeByteOrder() {
  return std::endian::native == std::endian::big ? ByteOrder::big : ByteOrder::little;
}

constexpr const char* toString(ByteOrder o) { return o == ByteOrder::big ? "big-endian" : "little-endian"; }

inline std::uint16_t loadU16(const std::uint8_t* p, ByteOrder o) {
  const auto b0 = static_cast<unsigned>(p[0]);
  const auto b1 = static_cast<unsigned>(p[1]);
  return static_cast<std::uint16_t>(o == ByteOrder::big ? (b0 << 8) | b1 : (b1 << 8) | b0);
}

inline std::uint32_t loadU32(const std::uint8_t* p, ByteOrder o) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) {
    const int k = o == ByteOrder::big ? i : 3 - i;
    v = (v << 8) | p[k];
  }
  return v;
}

inline std::uint64_t loadU64(const std::uint8_t* p, ByteOrder o) {
  std::uint64_t v = 0;
  for (int i = 0; i < 8; ++i) {
    const int k = o == ByteOrder::big ? i : 7 - i;
    v = (v << 8) | p[k];
  }
  return v;
}

inline void storeU16(std::uint8_t* p, std::uint16_t v, ByteOrder o) {
  const auto hi = static_cast<std::uint8_t>(v >> 8);
  const auto lo = static_cast<std::uint8_t>(v & 0xFFu);
  p[0] = o == ByteOrder::big ? hi : lo;
  p[1] = o == ByteOrder::big ? lo : hi;
}

inline void storeU32(std::uint8_t* p, std::uint32_t v, ByteOrder o) {
  for (int i = 0; i < 4; ++i) {
    const int k = o == ByteOrder::big ? 3 - i : i;
    p[k] = static_cast<std::uint8_t>(v >> (8 * i));
  }
}

inline void storeU64(std::uint8_t* p, std::uint64_t v, ByteOrder o) {
  for (int i = 0; i < 8; ++i) {
    const int k = o == ByteOrder::big ? 7 - i : i;
    p[k] = static_cast<std::uint8_t>(v >> (8 * i));
  }
}

// IEEE-754 binary32/binary64 travel as their bit patterns (CIGI and CANaerospace both say so).
inline float loadF32(const std::uint8_t* p, ByteOrder o) { return std::bit_cast<float>(loadU32(p, o)); }
inline double loadF64(const std::uint8_t* p, ByteOrder o) { return std::bit_cast<double>(loadU64(p, o)); }
inline void storeF32(std::uint8_t* p, float v, ByteOrder o) { storeU32(p, std::bit_cast<std::uint32_t>(v), o); }
inline void storeF64(std::uint8_t* p, double v, ByteOrder o) { storeU64(p, std::bit_cast<std::uint64_t>(v), o); }

}  // namespace skyig::protocol
