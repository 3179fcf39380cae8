#include "commands/dome_command.h"

#include "physics/common/parse_number.h"

#include "calibration/calibration_error.h"
#include "calibration/mpcdi_writer.h"
#include "render/output_file.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace skyig::services {

namespace {

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, sep)) parts.push_back(part);
  if (!text.empty() && text.back() == sep) parts.emplace_back();
  return parts;
}

double parseNumber(const std::string& word, const std::string& what, const std::string& whole) {
  const std::optional<double> v = parseWholeNumber(word);
  if (!v) throw std::invalid_argument("--projector \"" + whole + "\": " + what + " \"" + word + "\" is not a number");
  return *v;
}

std::vector<double> parseNumbers(const std::string& word, std::size_t count, const std::string& what,
                                 const std::string& whole) {
  const auto parts = split(word, ',');
  if (parts.size() != count)
    throw std::invalid_argument("--projector \"" + whole + "\": " + what + " \"" + word + "\" needs " +
                                std::to_string(count) + " comma-separated numbers");
  std::vector<double> out;
  for (const auto& p : parts) out.push_back(parseNumber(p, what, whole));
  return out;
}

void parseResolution(const std::string& word, int& width, int& height, const std::string& flag) {
  const auto x = word.find('x');
  int w = 0, h = 0;
  char extra = 0;
  if (x == std::string::npos || std::sscanf(word.c_str(), "%dx%d%c", &w, &h, &extra) != 2 || w < 2 || h < 2 ||
      w > 16384 || h > 16384)
    throw std::invalid_argument(flag + ": resolution \"" + word + "\" is not WIDTHxHEIGHT (2 to 16384 pixels)");
  width = w;
  height = h;
}

glm::dvec3 parsePosition(const std::string& word, const std::string& flag) {
  const auto parts = split(word, ',');
  if (parts.size() != 3) throw std::invalid_argument(flag + " \"" + word + "\": needs x,y,z in metres");
  glm::dvec3 p(0.0);
  for (int i = 0; i < 3; ++i) {
    std::size_t used = 0;
    double v = 0.0;
    try {
      v = std::stod(parts[static_cast<std::size_t>(i)], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != parts[static_cast<std::size_t>(i)].size() || !std::isfinite(v))
      throw std::invalid_argument(flag + " \"" + word + "\": \"" + parts[static_cast<std::size_t>(i)] + "\" is not a number");
    p[i] = v;
  }
  return p;
}

}  // namespace

calibration::DomeProjector parseDomeProjector(const std::string& text) {
  const auto fields = split(text, ':');
  if (fields.size() != 4 && fields.size() != 5)
    throw std::invalid_argument("--projector \"" + text + "\": expected NAME:yaw,pitch,roll:hfov,vfov:WxH[:x,y,z]");
  calibration::DomeProjector p;
  p.name = fields[0];
  if (p.name.empty() || p.name.find_first_of("/\\ \"<>&") != std::string::npos)
    throw std::invalid_argument("--projector \"" + text + "\": name \"" + p.name +
                                "\" must be non-empty, without spaces, slashes or XML specials");
  const auto att = parseNumbers(fields[1], 3, "orientation", text);
  p.orientation = {att[0], att[1], att[2]};
  const auto fov = parseNumbers(fields[2], 2, "field of view", text);
  for (double f : fov)
    if (!(f > 0.0 && f < 178.0))
      throw std::invalid_argument("--projector \"" + text + "\": field of view " + fields[2] +
                                  " must be in (0, 178) degrees");
  p.lens = {fov[0] / 2, fov[0] / 2, fov[1] / 2, fov[1] / 2};
  parseResolution(fields[3], p.width, p.height, "--projector \"" + text + "\"");
  if (fields.size() == 5) p.position = parsePosition(fields[4], "--projector \"" + text + "\" position");
  return p;
}

void registerDomeCommand(CLI::App& app, int& exitCode, std::ostream& out, std::ostream& err) {
  struct Options {
    std::string outPath;
    double radius = 3.0;
    std::string eye = "0,0,0";
    double contrast = 2000.0;
    int warpStep = 8;
    std::string profile = "2d";
    std::string resolution = "1920x1200";
    std::vector<std::string> projectors;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "dome", "Write a VESA MPCDI file for a spherical dome from its geometry (a starting point, not a calibration)");
  cmd->add_option("--out", o->outPath, "The .mpcdi file to write (replaced atomically)")->required();
  cmd->add_option("--radius", o->radius, "Dome radius, metres (default 3)");
  cmd->add_option("--eye", o->eye, "Eyepoint x,y,z in metres from the dome's centre, body axes x forward, y right, "
                                   "z down (default 0,0,0)");
  cmd->add_option("--contrast", o->contrast, "Projector contrast, white:black (default 2000), for the beta maps");
  cmd->add_option("--warp-step", o->warpStep, "Warp grid: a node every N projector pixels and the last (default 8)");
  cmd->add_option("--profile", o->profile, "MPCDI profile: 2d (image coordinates) or a3 (dome points) (default 2d)");
  cmd->add_option("--resolution", o->resolution, "Resolution of the default five projectors (default 1920x1200)");
  cmd->add_option("--projector", o->projectors,
                  "NAME:yaw,pitch,roll:hfov,vfov:WxH[:x,y,z] (repeatable; replaces the default five): "
                  "orientation in degrees, full fields of view in degrees, position in metres");
  cmd->callback([o, &exitCode, &out, &err]() {
    calibration::Dome dome;
    try {
      int width = 0, height = 0;
      parseResolution(o->resolution, width, height, "--resolution");
      dome = calibration::defaultHelicopterDome(width, height);
      if (!o->projectors.empty()) {
        dome.projectors.clear();
        for (const auto& text : o->projectors) {
          dome.projectors.push_back(parseDomeProjector(text));
          for (std::size_t i = 0; i + 1 < dome.projectors.size(); ++i)
            if (dome.projectors[i].name == dome.projectors.back().name)
              throw std::invalid_argument("--projector \"" + text + "\": the name \"" + dome.projectors.back().name +
                                          "\" is taken");
        }
      }
      if (!(o->radius > 0.0) || !std::isfinite(o->radius))
        throw std::invalid_argument("--radius " + std::to_string(o->radius) + ": not a positive length");
      dome.radius = o->radius;
      dome.eye = parsePosition(o->eye, "--eye");
      if (!(o->contrast >= 1.0) || !std::isfinite(o->contrast))
        throw std::invalid_argument("--contrast " + std::to_string(o->contrast) + ": not a ratio of at least 1");
      dome.contrast = o->contrast;
      if (o->warpStep < 1) throw std::invalid_argument("--warp-step " + std::to_string(o->warpStep) + ": not a positive pixel count");
      dome.warpStep = o->warpStep;
      calibration::MpcdiWriteOptions options;
      options.profile = calibration::parseMpcdiProfile(o->profile);
      render::checkOutputPath(o->outPath);  // before the work: a bad path fails fast

      const auto start = std::chrono::steady_clock::now();
      int shownTenth = -1;
      auto progress = [&](double fraction) {
        if (std::chrono::steady_clock::now() - start < std::chrono::seconds(1)) return;
        const int tenth = static_cast<int>(fraction * 10.0);
        if (tenth == shownTenth) return;
        shownTenth = tenth;
        err << "skyig dome: " << tenth * 10 << "%\n" << std::flush;
      };
      calibration::DomeSummary summary;
      const auto cals = calibration::generateDome(dome, &summary, progress);
      const std::string bytes = calibration::encodeMpcdi(dome, cals, options);
      render::writeOutputFile(o->outPath, bytes);

      char line[256];
      out << "wrote " << o->outPath << " (MPCDI 2.0, profile " << o->profile << ", " << bytes.size()
          << " bytes): dome radius " << dome.radius << " m, " << cals.size() << " regions\n";
      for (std::size_t p = 0; p < cals.size(); ++p) {
        const auto& c = cals[p];
        std::snprintf(line, sizeof line,
                      "  %-12s %dx%d  camera yaw %7.2f pitch %7.2f roll %7.2f  frustum L %.2f R %.2f D %.2f U %.2f  "
                      "warp %dx%d  alpha %.3f..%.3f\n",
                      c.region.c_str(), c.width, c.height, c.camera.offset.yawDeg, c.camera.offset.pitchDeg,
                      c.camera.offset.rollDeg, c.camera.frustum.leftDeg, c.camera.frustum.rightDeg,
                      c.camera.frustum.downDeg, c.camera.frustum.upDeg, c.warp.width, c.warp.height,
                      summary.minAlpha[p], summary.maxAlpha[p]);
        out << line;
      }
      for (const auto& ov : summary.overlaps) {
        std::snprintf(line, sizeof line, "  overlap %s / %s: %.1f degrees\n", cals[ov.a].region.c_str(),
                      cals[ov.b].region.c_str(), ov.degrees);
        out << line;
      }
      out << "  at most " << summary.maxOverlap << " projectors light one point; black floor lifted to "
          << summary.maxOverlap << " x 1/" << dome.contrast << " of white\n";
      exitCode = 0;
    } catch (const std::invalid_argument& e) {
      err << "skyig dome: " << e.what() << '\n';
      exitCode = 2;
    } catch (const calibration::CalibrationError& e) {
      err << "skyig dome: " << e.what() << '\n';
      exitCode = 2;
    }
  });
}

void registerDomeCommand(CLI::App& app, int& exitCode) { registerDomeCommand(app, exitCode, std::cout, std::cerr); }

}  // namespace skyig::services
