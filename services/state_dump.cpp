#include "services/state_dump.h"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>

namespace skyig::services {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

nlohmann::json hostJson(const HostState& h) {
  nlohmann::json j = {{"visibility_m", h.visibilityM}, {"humidity_pct", h.humidityPct}};
  if (h.ownshipValid)
    j.update({{"lat", h.ownship.latitudeDeg}, {"lon", h.ownship.longitudeDeg}, {"alt", h.ownship.altitudeM},
              {"yaw", h.ownship.yawDeg}, {"pitch", h.ownship.pitchDeg}, {"roll", h.ownship.rollDeg}});
  if (h.timeValid) j["utc"] = ephemeris::formatIso8601Utc(h.utc);
  return j;
}

}  // namespace

StateDump::StateDump(const std::string& path) : path_(path) {
  file_ = std::fopen(path.c_str(), "w");
  if (!file_) throw std::runtime_error("cannot write the state dump " + path + ": " + std::strerror(errno));
}

StateDump::~StateDump() {
  if (file_) std::fclose(file_);
}

void StateDump::write(std::uint64_t igFrame, const HostSnapshot* host, const sky::SkyState& used) {
  const auto& o = used.observer;
  nlohmann::json line = {
      {"ig_frame", igFrame},
      {"host_frame", host ? nlohmann::json(host->state.hostFrame) : nlohmann::json(nullptr)},
      {"host", host ? hostJson(host->state) : nlohmann::json(nullptr)},
      {"used",
       {{"lat", o.latitudeDeg}, {"lon", o.longitudeDeg}, {"alt", o.heightM}, {"yaw", o.attitude.yawDeg},
        {"pitch", o.attitude.pitchDeg}, {"roll", o.attitude.rollDeg}, {"utc", ephemeris::formatIso8601Utc(o.utc)},
        {"visibility_m", host ? host->state.visibilityM : 50000.0}}},
      {"sun", {{"azimuth_deg", used.sunAzimuth / kDeg}, {"altitude_deg", used.sunAltitude / kDeg},
               {"altitude_refracted_deg", used.sunApparentAltitude / kDeg}}},
  };
  if (used.ephemeris) {
    const auto& m = used.ephemeris->moon;
    line["moon"] = {{"azimuth_deg", m.azimuthRad / kDeg}, {"altitude_deg", m.altitudeRad / kDeg},
                    {"altitude_refracted_deg", m.altitudeRefractedRad / kDeg}};
  }
  const std::string text = line.dump() + "\n";
  // One line per frame, flushed: a crash loses at most the frame being written.
  std::fwrite(text.data(), 1, text.size(), file_);
  std::fflush(file_);
}

void writeStatsFile(const std::string& path, const NodeStats& stats) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp);
    out << stats.toJson().dump(2) << "\n";
    if (!out) return;  // statistics are best effort: never stop the node for them
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
}

}  // namespace skyig::services
