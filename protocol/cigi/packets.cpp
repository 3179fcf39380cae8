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

}  // namespace skyig::protocol::cigi
