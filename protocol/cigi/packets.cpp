#include "protocol/cigi/packets.h"

#include <array>

namespace skyig::protocol::cigi {

namespace {

struct PacketInfo {
  PacketId id;
  std::uint8_t size;
  const char* name;
};

// In the order of the Packet variant's alternatives. Sizes: CIGI 3.3 ICD (3.2+ for IG
// Control, Rate Control and Start of Frame).
constexpr std::array<PacketInfo, kPacketTypeCount> kInfo{{
    {PacketId::igControl, 24, "IG Control"},
    {PacketId::entityControl, 48, "Entity Control"},
    {PacketId::rateControl, 32, "Rate Control"},
    {PacketId::celestialSphereControl, 16, "Celestial Sphere Control"},
    {PacketId::atmosphereControl, 32, "Atmosphere Control"},
    {PacketId::environmentalRegionControl, 48, "Environmental Region Control"},
    {PacketId::weatherControl, 56, "Weather Control"},
    {PacketId::viewControl, 32, "View Control"},
    {PacketId::viewDefinition, 32, "View Definition"},
    {PacketId::sensorControl, 24, "Sensor Control"},
    {PacketId::startOfFrame, 24, "Start of Frame"},
}};

const PacketInfo* find(PacketId id) {
  for (const auto& i : kInfo)
    if (i.id == id) return &i;
  return nullptr;
}

}  // namespace

PacketId packetId(const Packet& p) { return kInfo[p.index()].id; }

std::uint8_t packetSize(PacketId id) {
  const PacketInfo* i = find(id);
  return i != nullptr ? i->size : 0;
}

const char* packetName(PacketId id) {
  const PacketInfo* i = find(id);
  return i != nullptr ? i->name : "unknown packet";
}

const char* packetName(std::size_t variantIndex) {
  return variantIndex < kInfo.size() ? kInfo[variantIndex].name : "unknown packet";
}

namespace {

struct Packet4Info {
  std::uint16_t id;
  std::uint16_t size;  // 0: no CIGI 4 mapping
  const char* name;
};

// CIGI 4.0 ids and sizes (CIGI 4.0 ICD, SISO-STD-013-2014, as implemented by the CIGI Class
// Library 4.0 port, captainflasmr/cigi-ccl_4_0), in the Packet variant's order.
constexpr std::array<Packet4Info, kPacketTypeCount> kInfo4{{
    {kCigi4IgControl, 24, "IG Control"},
    {kCigi4EntityPositionControl, 48, "Entity Position Control"},
    {0, 0, "Rate Control"},
    {kCigi4CelestialSphereControl, 24, "Celestial Sphere Control"},
    {kCigi4AtmosphereControl, 32, "Atmosphere Control"},
    {0, 0, "Environmental Region Control"},
    {kCigi4WeatherControl, 72, "Weather Control"},
    {kCigi4ViewControl, 40, "View Control"},
    {kCigi4ViewDefinition, 40, "View Definition"},
    {kCigi4SensorControl, 32, "Sensor Control"},
    {kCigi4StartOfFrame, 24, "Start of Frame"},
}};

}  // namespace

std::uint16_t packetId4(std::size_t variantIndex) { return variantIndex < kInfo4.size() ? kInfo4[variantIndex].id : 0; }

std::uint16_t packetSize4(std::size_t variantIndex) {
  return variantIndex < kInfo4.size() ? kInfo4[variantIndex].size : 0;
}

std::size_t variantIndexOf4(std::uint16_t id4) {
  for (std::size_t i = 0; i < kInfo4.size(); ++i)
    if (kInfo4[i].size != 0 && kInfo4[i].id == id4) return i;
  return kPacketTypeCount;
}

const char* packetName4(std::uint16_t id4) {
  const std::size_t i = variantIndexOf4(id4);
  return i < kInfo4.size() ? kInfo4[i].name : "unknown packet";
}

}  // namespace skyig::protocol::cigi
