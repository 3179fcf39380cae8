#pragma once
// The files of one rendered frame, as `skyig replay DIR` and `skyig serve --save-frames DIR`
// write them (one piece of code, so a replay's frames and the node's compare file by file):
// DIR/frame_000123_2026-06-21T19-00-04.123Z[_channel].exr (cd/m^2) and .png (as displayed).
#include "calibration/projector.h"
#include "ephemeris/time.h"
#include "render/image_io.h"
#include "render/sky_renderer.h"
#include "sky/channel.h"

#include <cstdint>
#include <string>

namespace skyig::services {

// DIR/frame_NNNNNN_<sim time, no colons>[_channel]: frame number and sim time.
std::string frameStem(const std::string& dir, std::uint64_t frame, const ephemeris::UtcTime& t,
                      const std::string& channel);

// Writes the renderer's last frame of `channel` (its HDR target as EXR, its display target as
// PNG for the channel's display gamma) to stem.exr / stem.png; returns how many files it wrote.
// For a channel drawn for `projector` (SkyRenderer::drawProjector): what the projector is sent
// (PNG) and the light it adds to the screen (EXR, with the projector's attributes).
int writeFrameFiles(const render::SkyRenderer& renderer, const std::string& stem, const sky::ChannelConfig& channel,
                    bool exr, bool png, const render::ImageAttributes& attributes,
                    const calibration::ProjectorCalibration* projector = nullptr);

// The same to named files (`skyig render`'s --exr and --png; "" writes none), for any path
// render/output_file.h accepts.
int writeFrameImages(const render::SkyRenderer& renderer, const std::string& exrPath, const std::string& pngPath,
                     const sky::ChannelConfig& channel, const render::ImageAttributes& attributes,
                     const calibration::ProjectorCalibration* projector = nullptr);

}  // namespace skyig::services
