#include "node/frame/frame_metadata.h"

#include "physics/weather/cloud_layer.h"

#include "node/common/version.h"
#include "sky/camera.h"
#include "physics/goggle/nvis_response.h"
#include "physics/atmosphere/conditions.h"
#include "physics/common/units.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace skyig::services {

namespace {

using skyig::kDeg;

// OpenEXR's capDate, "YYYY:MM:DD hh:mm:ss" (ImfStandardAttributes.h); skyig's local time is UTC.
std::string capDate(const ephemeris::UtcTime& t) {
  const int whole = std::clamp(static_cast<int>(std::floor(t.secondsOfDay)), 0, 86399);  // a leap second shows :59
  char buf[64];
  std::snprintf(buf, sizeof buf, "%04d:%02d:%02d %02d:%02d:%02d", t.year, t.month, t.day, whole / 3600,
                (whole / 60) % 60, whole % 60);
  return buf;
}

}  // namespace

render::Matrix44f worldToCamera(const sky::Attitude& ownship, const sky::Attitude& channelOffset) {
  // Columns of eyeToEnu: the eye's forward, right and down axes in ENU. OpenEXR's camera axes
  // are right, up (= -down) and forward; with row vectors, column j of M is camera axis j.
  const glm::dmat3 eye = sky::eyeToEnu(ownship, channelOffset);
  const glm::dvec3 axes[3] = {eye[1], -eye[2], eye[0]};
  render::Matrix44f m;
  for (std::size_t row = 0; row < 3; ++row)
    for (std::size_t col = 0; col < 3; ++col)
      m.m[row][col] = static_cast<float>(axes[col][static_cast<glm::length_t>(row)]);
  m.m[3][3] = 1.0f;
  return m;
}

render::ImageAttributes frameAttributes(const sky::SkyState& s, const sky::Attitude& ownship,
                                        const sky::ChannelConfig& c) {
  const auto& o = s.observer;
  render::ImageAttributes a{
      // OpenEXR standard attributes (fixed types: float, string, m44f).
      {"latitude", static_cast<float>(o.latitudeDeg)},
      {"longitude", static_cast<float>(o.longitudeDeg)},
      {"altitude", static_cast<float>(o.heightM)},
      {"capDate", capDate(o.utc)},
      {"utcOffset", 0.0f},  // capDate is UTC
      {"worldToCamera", worldToCamera(ownship, c.offset)},
      // skyig's: full precision, the channel's own geometry and the sky that was drawn.
      {"skyig:version", std::string(kVersion)},
      {"skyig:utc", ephemeris::formatIso8601Utc(o.utc)},
      {"skyig:latitude_deg", o.latitudeDeg},
      {"skyig:longitude_deg", o.longitudeDeg},
      {"skyig:altitude_m", o.heightM},
      {"skyig:ownship_yaw_deg", ownship.yawDeg},
      {"skyig:ownship_pitch_deg", ownship.pitchDeg},
      {"skyig:ownship_roll_deg", ownship.rollDeg},
      {"skyig:channel", c.name},
      {"skyig:channel_yaw_deg", c.offset.yawDeg},
      {"skyig:channel_pitch_deg", c.offset.pitchDeg},
      {"skyig:channel_roll_deg", c.offset.rollDeg},
      {"skyig:frustum_left_deg", c.frustum.leftDeg},
      {"skyig:frustum_right_deg", c.frustum.rightDeg},
      {"skyig:frustum_up_deg", c.frustum.upDeg},
      {"skyig:frustum_down_deg", c.frustum.downDeg},
      {"skyig:sky_model", std::string(sky::toString(s.conditions.model))},
      {"skyig:cie_type", s.conditions.cieType},
      {"skyig:turbidity", s.conditions.turbidity},
      {"skyig:sun_azimuth_deg", s.sunAzimuth / kDeg},
      {"skyig:sun_altitude_deg", s.sunAltitude / kDeg},
      {"skyig:adaptation_cd_m2", s.worldAdaptationLuminance},
      {"skyig:units", std::string("linear Rec.709, Y in cd/m^2")},
  };
  // The weather drawn: the tables' visibility, and the fog layers over them (0: none).
  if (s.conditions.atmosphere) {
    a["skyig:visibility_tables_km"] = atmosphere::visibilityOf(s.conditions.atmosphere->config().medium);
    const sky::FogSpec layers[3] = {s.conditions.haze, s.conditions.fog, s.conditions.precipitation};
    const char* names[3] = {"haze", "fog", "precipitation"};
    for (int i = 0; i < 3; ++i) {
      const std::string p = std::string("skyig:") + names[i];
      a[p + "_visibility_km"] = layers[i].visibilityKm;
      a[p + "_bottom_m"] = layers[i].bottomM;
      a[p + "_top_m"] = layers[i].topM;
      a[p + "_transition_m"] = layers[i].transitionM;
    }
    // The precipitation's particles: dust tints (an albedo below 1 per Rec.709 channel).
    const sky::FogSpec& p = s.conditions.precipitation;
    a["skyig:precipitation_albedo_rgb"] = std::to_string(p.albedo[0]) + " " + std::to_string(p.albedo[1]) + " " +
                                          std::to_string(p.albedo[2]);
  }
  // The host's or the configuration's cloud layers as drawn: "stratus base 300 m,
  // 400 m thick, 100 % cover, severity 2" or "off".
  for (std::size_t i = 0; i < sky::kCloudLayers; ++i)
    a["skyig:cloud_layer_" + std::to_string(i + 1)] = weather::describe(s.conditions.clouds[i]);
  if (sky::isGoggle(c)) {
    // A goggle's image is its NVIS radiance (render/sky_renderer.h), drawn with the goggle's
    // frustum (sky::goggleFrustum).
    const bool classA = c.band == sky::SpectralBand::NvisClassA;
    const sky::Frustum f = sky::goggleFrustum(c);
    a["skyig:units"] = std::string(classA ? "NVIS radiance, class A" : "NVIS radiance, class B") +
                       ": W m^-2 sr^-1, the integral over 450-930 nm of the class's relative response (peak 1) times "
                       "the spectral radiance (MIL-STD-3009 without G_max), the same in R, G and B";
    a["skyig:nvis_class"] = std::string(classA ? "A" : "B");
    a["skyig:nvis_response_provisional"] = sky::nvis::kNvisResponseProvisional ? 1 : 0;
    a["skyig:goggle_phosphor"] = std::string(c.goggle.phosphor == sky::Phosphor::P43 ? "P43" : "P45");
    a["skyig:goggle_field_of_view_deg"] = c.goggle.fieldOfViewDeg;
    a["skyig:frustum_left_deg"] = f.leftDeg;
    a["skyig:frustum_right_deg"] = f.rightDeg;
    a["skyig:frustum_up_deg"] = f.upDeg;
    a["skyig:frustum_down_deg"] = f.downDeg;
  }
  return a;
}

void addProjectorAttributes(render::ImageAttributes& attributes, const calibration::ProjectorCalibration& projector) {
  attributes["skyig:projector"] = projector.source;
  attributes["skyig:projector_region"] = projector.region;
  attributes["skyig:projector_width"] = projector.width;
  attributes["skyig:projector_height"] = projector.height;
  attributes["skyig:units"] = std::string("linear Rec.709, Y in cd/m^2: the light this projector adds (warped, times its blend)");
}

}  // namespace skyig::services
