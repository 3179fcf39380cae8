#pragma once
// `skyig dome`: a VESA MPCDI file for a spherical dome computed from its geometry
// (calibration/dome.h, calibration/mpcdi_writer.h): a starting point and the fixture of the
// projector tests, never a replacement for the projection vendor's calibration
// (docs/projectors.md, "A dome from geometry").
#include "calibration/dome.h"

#include <CLI/CLI.hpp>

#include <iosfwd>
#include <string>

namespace skyig::services {

// `NAME:yaw,pitch,roll:hfov,vfov:WxH[:x,y,z]`: orientation in degrees (body frame), the full
// horizontal and vertical fields of view of a centred lens in degrees, the resolution, the
// position in metres from the dome's centre (default the centre). std::invalid_argument naming
// the value and what is wrong with it.
calibration::DomeProjector parseDomeProjector(const std::string& text);

// Adds the `dome` subcommand. Bad flag values exit 2 naming the value (an unwritable --out
// through render::OutputPathError, which main turns into 2).
void registerDomeCommand(CLI::App& app, int& exitCode, std::ostream& out, std::ostream& err);
void registerDomeCommand(CLI::App& app, int& exitCode);  // std::cout / std::cerr

}  // namespace skyig::services
