#include "commands/render_command.h"

#include "ephemeris/time.h"
#include "render/gl/gl_context.h"
#include "render/image_io.h"
#include "render/output_file.h"
#include "render/sky_renderer.h"
#include "commands/common_options.h"
#include "node/frame/frame_files.h"
#include "node/frame/frame_metadata.h"
#include "node/config/projector_channel.h"
#include "node/config/sky_data.h"
#include "physics/common/units.h"

#include <spdlog/spdlog.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>

namespace skyig::services {

namespace {

using skyig::kDeg;

struct RenderOptions {
  SkyOptions sky;
  std::string channel;
  bool allChannels = false;
  std::string size;
  std::string exrPath;
  std::string pngPath;
  bool projector = false;
  std::string goggle;    // "A" or "B": the channels as goggles of that class
  std::string phosphor;  // "P43" or "P45"
};

// "out/sky.exr" + "left" -> "out/sky_left.exr", for one file per channel.
std::string perChannelPath(const std::string& path, const std::string& channel) {
  const std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + "_" + channel + p.extension().string())).string();
}

int run(const RenderOptions& opt) {
  if (opt.exrPath.empty() && opt.pngPath.empty()) throw ConfigError("render: give --exr PATH and/or --png PATH");
  NodeConfig config = opt.sky.resolve();
  std::vector<sky::ChannelConfig> channels;
  if (opt.allChannels) {
    channels = config.channels;
  } else if (!opt.channel.empty()) {
    for (const auto& c : config.channels)
      if (c.name == opt.channel) channels.push_back(c);
    if (channels.empty()) {
      std::string names;
      for (const auto& c : config.channels) names += (names.empty() ? "" : ", ") + c.name;
      throw ConfigError("--channel: no channel named \"" + opt.channel + "\" (the configuration has: " + names + ")");
    }
  } else {
    channels.push_back(config.channels.front());
  }
  // Every calibration is read before anything else: a bad file stops here (exit 2). A channel
  // with a projector is drawn with its region's camera, at the projector's size by default.
  std::vector<ProjectorChannel> projected;
  std::string plain;
  for (const auto& c : channels) {
    projected.push_back(loadProjectorChannel(c, config.projectorOf(c.name)));
    if (!projected.back().projector) plain += (plain.empty() ? "" : ", ") + c.name;
  }
  if (opt.projector && !plain.empty())
    throw ConfigError("--projector: channel(s) " + plain + " have no [channel.projector] in the configuration");
  channels.clear();
  for (const auto& p : projected) channels.push_back(p.channel);
  if (!opt.size.empty())
    for (auto& c : channels) parseSize(opt.size, c.width, c.height);
  // With --projector the outputs are the projector's pixels, whatever --size says: say what it
  // does change (the channel's image the projector's warp reads) instead of ignoring it quietly.
  if (opt.projector && !opt.size.empty())
    std::fprintf(stderr, "render: --size %s sets the channel image each projector's warp reads; the outputs keep the "
                         "projector's resolution from its calibration\n", opt.size.c_str());
  for (auto& c : channels) {  // the goggle switched on, as the host's Sensor Control does
    if (!opt.goggle.empty()) {
      c.goggle.nvisClass = opt.goggle == "A" ? sky::SpectralBand::NvisClassA : sky::SpectralBand::NvisClassB;
      c.band = c.goggle.nvisClass;
    }
    if (!opt.phosphor.empty()) c.goggle.phosphor = opt.phosphor == "P43" ? sky::Phosphor::P43 : sky::Phosphor::P45;
  }

  // Every output is checked before any work (the tables included), so a bad path fails fast
  // and writes nothing; two outputs naming one file would leave only the second.
  const bool perChannel = opt.allChannels && channels.size() > 1;
  auto outPath = [&](const std::string& p, const sky::ChannelConfig& c) {
    return perChannel && p != "-" ? perChannelPath(p, c.name) : p;
  };
  std::vector<std::pair<std::string, std::string>> outputs;
  for (const auto& c : channels) {
    if (!opt.exrPath.empty()) render::checkWritable(outPath(opt.exrPath, c));
    if (!opt.pngPath.empty()) render::checkWritable(outPath(opt.pngPath, c));
    outputs.emplace_back("--exr", outPath(opt.exrPath, c));
    outputs.emplace_back("--png", outPath(opt.pngPath, c));
  }
  render::checkDistinctOutputs(outputs);
  // With an image on standard output, the report goes to stderr.
  std::FILE* report = opt.exrPath == "-" || opt.pngPath == "-" ? stderr : stdout;
  loadSkyData(config);

  sky::SkyState state = sky::buildSkyState(config.observer, config.sky, opt.sky.sunOverride());
  // Mapped for the channels' displays as the node maps its states: the same curves, and the
  // same faint layers left out where no display would show them (sky/shown_layers.h).
  std::vector<sky::DisplayParams> displays;
  for (const sky::ChannelConfig& c : channels) displays.push_back(c.display);
  sky::mapForDisplays(state, displays);
  const auto context = render::createHeadlessContext();
  spdlog::info("GL: {} ({}, {})", context->info().renderer, context->info().version, context->info().platform);
  render::SkyRenderer renderer;
  std::fprintf(report, "sky: %s, sun azimuth %.2f deg, altitude %.2f deg, adaptation %.4g cd/m^2\n",
               std::string(sky::toString(state.conditions.model)).c_str(), state.sunAzimuth / kDeg,
               state.sunAltitude / kDeg, state.worldAdaptationLuminance);
  if (state.ephemeris)
    spdlog::info("sky: the sun's sky {}, moonlit sky {}, the night's own light {} (sky/shown_layers.h)",
                 state.shown.sunlitSky ? "drawn" : "left out, no display would show it",
                 state.shown.moonlitSky ? "drawn" : "left out, no display would show it",
                 state.shown.nightLight ? "drawn" : "left out, no display would show it");
  for (std::size_t i = 0; i < channels.size(); ++i) {
    const sky::ChannelConfig& c = channels[i];
    const auto start = std::chrono::steady_clock::now();
    // --projector: what the projector is sent (PNG) and the light it adds to the screen (EXR).
    if (opt.projector) renderer.drawProjector(state, c, projected[i].projector);
    else renderer.draw(state, c);
    writeFrameImages(renderer, opt.exrPath.empty() ? "" : outPath(opt.exrPath, c),
                     opt.pngPath.empty() ? "" : outPath(opt.pngPath, c), c,
                     frameAttributes(state, state.observer.attitude, c),
                     opt.projector ? projected[i].projector.get() : nullptr);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const int w = opt.projector ? projected[i].projector->width : c.width;
    const int h = opt.projector ? projected[i].projector->height : c.height;
    std::fprintf(report, "%s %s: %dx%d in %.1f ms ->%s%s\n", opt.projector ? "projector" : "channel", c.name.c_str(), w, h, ms,
                 opt.exrPath.empty() ? "" : (" " + outPath(opt.exrPath, c)).c_str(),
                 opt.pngPath.empty() ? "" : (" " + outPath(opt.pngPath, c)).c_str());
  }
  return 0;
}

}  // namespace

void registerRenderCommand(CLI::App& app, int& exitCode) {
  auto opt = std::make_shared<RenderOptions>();
  CLI::App* c = app.add_subcommand("render", "Render one frame of one or all channels to OpenEXR and/or PNG, headless");
  opt->sky.add(*c);
  c->add_option("--channel", opt->channel, "Channel to render (default: the first)");
  c->add_flag("--all-channels", opt->allChannels, "Render every channel, one file each (NAME_CHANNEL.ext)");
  c->add_option("--size", opt->size,
                "Override the channel resolution, WIDTHxHEIGHT (with --projector: the image the warp reads; the "
                "outputs keep the projector's resolution)");
  c->add_option("--exr", opt->exrPath, "OpenEXR output: float RGBA, linear Rec.709, values in cd/m^2");
  c->add_option("--png", opt->pngPath, "PNG output: 8-bit, tone reproduced for the channel's display");
  c->add_flag("--projector", opt->projector,
              "Write what each channel's projector ([channel.projector]) is sent: the PNG warped and blended at the "
              "projector's resolution, the EXR the light it adds to the screen (cd/m^2 times its blend)");
  c->add_option("--goggle", opt->goggle,
                 "Render the channels as night-vision goggles of NVIS class A or B: the EXR holds the NVIS radiance "
                 "(W m^-2 sr^-1), the PNG the goggle's screen (docs/nvis.md)")
      ->check(CLI::IsMember({"A", "B"}));
  c->add_option("--phosphor", opt->phosphor, "The goggle's phosphor: P43 (green) or P45 (white); default the channel's")
      ->check(CLI::IsMember({"P43", "P45"}));
  c->callback([opt, &exitCode] { exitCode = run(*opt); });
}

}  // namespace skyig::services
