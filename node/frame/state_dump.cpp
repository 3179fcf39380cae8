#include "node/frame/state_dump.h"

#include "tables/parameter_hash.h"
#include "physics/weather/cloud_layer.h"
#include "physics/weather/precipitation.h"

#include "render/output_file.h"
#include "physics/common/units.h"

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>

namespace skyig::services {

namespace {

using skyig::kDeg;

nlohmann::json fogJson(const sky::FogSpec& f) {
  return {{"visibility_km", f.visibilityKm}, {"bottom_m", f.bottomM}, {"top_m", f.topM},
          {"transition_m", f.transitionM}, {"asymmetry", f.asymmetry}, {"albedo", f.albedo}};
}

nlohmann::json cloudJson(const sky::CloudLayer& l) {
  if (!l.enabled) return {{"enabled", false}};
  return {{"enabled", true},           {"type", weather::toString(l.type)}, {"base_m", l.baseM},
          {"thickness_m", l.thicknessM}, {"coverage_pct", l.coveragePct},   {"severity", l.severity},
          {"visibility_m", l.visibilityM}, {"transition_m", l.transitionM}, {"top_transition_m", l.topTransitionM},
          {"scud", l.scud},             {"scud_frequency_pct", l.scudFrequencyPct}, {"top_scud", l.topScud},
          {"top_scud_frequency_pct", l.topScudFrequencyPct}, {"wind_speed_mps", l.windSpeedMps},
          {"wind_from_deg", l.windFromDeg}};
}

nlohmann::json cloudsJson(const sky::CloudLayers& layers) {
  nlohmann::json j = nlohmann::json::array();
  for (const sky::CloudLayer& l : layers) j.push_back(cloudJson(l));
  return j;
}

nlohmann::json hostJson(const HostState& h) {
  nlohmann::json j = {{"visibility_m", h.visibilityM}, {"humidity_pct", h.humidityPct}, {"pressure_hpa", h.pressureHpa},
                      {"temperature_c", h.temperatureC}, {"star_field_intensity", h.starFieldIntensity}};
  if (h.ownshipValid)
    j.update({{"lat", h.ownship.latitudeDeg}, {"lon", h.ownship.longitudeDeg}, {"alt", h.ownship.heightM},
              {"yaw", h.ownship.attitude.yawDeg}, {"pitch", h.ownship.attitude.pitchDeg}, {"roll", h.ownship.attitude.rollDeg}});
  if (h.timeValid) j["utc"] = ephemeris::formatIso8601Utc(h.utc);
  if (h.groundFog) j["ground_fog"] = fogJson(*h.groundFog);
  for (std::size_t i = 0; i < h.precipitation.size(); ++i)
    if (h.precipitation[i])
      j["precipitation"][std::string(weather::toString(static_cast<weather::Precipitation>(i)))] = fogJson(*h.precipitation[i]);
  for (std::size_t i = 0; i < h.clouds.size(); ++i)
    if (h.clouds[i]) j["clouds"][std::to_string(i + 1)] = cloudJson(*h.clouds[i]);
  return j;
}

// The channel's night-vision goggle as the frame used it (configured, or switched and set by the
// host's Sensor Control): on or off, its class and phosphor, and its gain.
nlohmann::json goggleJson(const sky::ChannelConfig& c) {
  const sky::SpectralBand nvisClass = sky::isGoggle(c) ? c.band : c.goggle.nvisClass;
  return {{"on", sky::isGoggle(c)},
          {"class", nvisClass == sky::SpectralBand::NvisClassA ? "A" : "B"},
          {"phosphor", c.goggle.phosphor == sky::Phosphor::P43 ? "P43" : "P45"},
          {"automatic_gain", c.goggle.automaticGain},
          {"gain", c.goggle.gain}};
}

}  // namespace

StateDump::StateDump(const std::string& path) : path_(path) {
  const int fd = render::openOutputStream(path);  // in place: "-" is stdout, a FIFO stays one
  file_ = ::fdopen(fd, "w");
  if (!file_) {
    ::close(fd);
    throw std::runtime_error("cannot write the state dump " + path + ": " + std::strerror(errno));
  }
}

StateDump::~StateDump() {
  if (file_) std::fclose(file_);
}

void StateDump::write(std::uint64_t igFrame, const HostSnapshot* host, const sky::SkyState& used,
                      const FramePose& pose, double frameS, const std::vector<double>& channelGpuS) {
  const auto& o = used.observer;
  nlohmann::json views = nlohmann::json::array();
  for (const sky::ChannelConfig& c : pose.channels)
    views.push_back({{"channel", c.name},
                     {"yaw", c.offset.yawDeg}, {"pitch", c.offset.pitchDeg}, {"roll", c.offset.rollDeg},
                     {"left", c.frustum.leftDeg}, {"right", c.frustum.rightDeg},
                     {"down", c.frustum.downDeg}, {"up", c.frustum.upDeg}, {"goggle", goggleJson(c)}});
  nlohmann::json line = {
      {"ig_frame", igFrame},
      {"host_frame", host ? nlohmann::json(host->state.hostFrame) : nlohmann::json(nullptr)},
      {"host", host ? hostJson(host->state) : nlohmann::json(nullptr)},
      {"used",
       {{"lat", o.latitudeDeg}, {"lon", o.longitudeDeg}, {"alt", o.heightM}, {"yaw", pose.attitude.yawDeg},
        {"pitch", pose.attitude.pitchDeg}, {"roll", pose.attitude.rollDeg}, {"utc", ephemeris::formatIso8601Utc(o.utc)},
        {"pressure_hpa", o.pressureHpa}, {"temperature_c", o.temperatureC},
        {"star_field_intensity", used.conditions.starFieldIntensity},
        {"atmosphere", used.conditions.atmosphere
                           ? nlohmann::json(atmosphere::hexHash(atmosphere::parameterHash(used.conditions.atmosphere->config())))
                           : nlohmann::json(nullptr)},
        {"haze", fogJson(used.conditions.haze)}, {"fog", fogJson(used.conditions.fog)},
        {"precipitation", fogJson(used.conditions.precipitation)},
        {"clouds", cloudsJson(used.conditions.clouds)},
        {"adaptation_cd_m2", used.worldAdaptationLuminance}, {"scene_cd_m2", used.sceneLuminance},
        {"adaptation_gain", used.adaptationGain},
        {"views", views}}},
      {"sun", {{"azimuth_deg", used.sunAzimuth / kDeg}, {"altitude_deg", used.sunAltitude / kDeg},
               {"altitude_refracted_deg", used.sunApparentAltitude / kDeg}}},
  };
  // Tables blended from two visibility steps while the exact ones are built (the hash above is
  // the exact tables' they stand in for).
  if (used.conditions.atmosphere && used.conditions.atmosphere->blendOrigin()) {
    const auto& b = *used.conditions.atmosphere->blendOrigin();
    line["used"]["atmosphere_blend"] = {{"clearer_km", b.clearerKm}, {"hazier_km", b.hazierKm}, {"weight", b.weight}};
  }
  if (used.ephemeris) {
    const auto& m = used.ephemeris->moon;
    line["moon"] = {{"azimuth_deg", m.azimuthRad / kDeg}, {"altitude_deg", m.altitudeRad / kDeg},
                    {"altitude_refracted_deg", m.altitudeRefractedRad / kDeg}};
  }
  if (frameS >= 0.0) {
    nlohmann::json gpu = nlohmann::json::object();
    for (std::size_t i = 0; i < std::min(channelGpuS.size(), pose.channels.size()); ++i)
      gpu[pose.channels[i].name] = 1000.0 * channelGpuS[i];
    line["timing"] = {{"frame_ms", 1000.0 * frameS}, {"channel_gpu_ms", gpu}};
  }
  const std::string text = line.dump() + "\n";
  // One line per frame, flushed: a crash loses at most the frame being written.
  std::fwrite(text.data(), 1, text.size(), file_);
  std::fflush(file_);
}

void writeStatsFile(const std::string& path, const NodeStats& stats) {
  try {
    render::writeOutputFile(path, stats.toJson().dump(2) + "\n");
  } catch (const std::exception& e) {
    // Statistics are best effort: never stop the node for them; say so at most every 10 s.
    static std::atomic<std::int64_t> lastWarning{0};
    const std::int64_t now = std::chrono::duration_cast<std::chrono::seconds>(Clock::now().time_since_epoch()).count();
    if (now - lastWarning.exchange(now) >= 10) spdlog::warn("statistics not written: {}", e.what());
  }
}

}  // namespace skyig::services
