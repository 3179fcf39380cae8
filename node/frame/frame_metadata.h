#pragma once
// The OpenEXR header of one channel's frame, written the same way by `skyig render`, `serve
// --save-frames` and `replay` (docs/outputs.md, "EXR metadata"): where and when the frame was
// rendered, which channel it is (its own eyepoint offset and frustum, not only the ownship's
// attitude) and how world directions map to its image. Numbers are stored as numbers; OpenEXR's
// standard attributes (ImfStandardAttributes.h) are used where one exists.
#include "calibration/projector.h"
#include "render/image_io.h"
#include "sky/channel.h"
#include "sky/sky_state.h"

namespace skyig::services {

// OpenEXR's worldToCamera for a channel: the world is ENU at the eyepoint (x east, y north,
// z up: the sky is at infinity, so there is no translation); the camera space is OpenEXR's
// (x right, y up, z the viewing direction, left-handed), for row vectors p_cam = p_world M.
render::Matrix44f worldToCamera(const sky::Attitude& ownship, const sky::Attitude& channelOffset);

// The attributes of `channel`'s frame of `state`, drawn with the ownship's attitude `ownship`
// (the render thread's predicted attitude in serve and replay, the observer's in render).
render::ImageAttributes frameAttributes(const sky::SkyState& state, const sky::Attitude& ownship,
                                        const sky::ChannelConfig& channel);

// What a projector's EXR adds to its channel's attributes (`render --projector`): the
// calibration it was warped with and that its pixels are the light it contributes.
void addProjectorAttributes(render::ImageAttributes& attributes, const calibration::ProjectorCalibration& projector);

}  // namespace skyig::services
