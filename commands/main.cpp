// skyig: the sky image generator of a helicopter flight simulator. One executable, one
// subcommand per use (docs/design.md, "Interfaces people and tests rely on").
#include "ephemeris/data_files.h"
#include "render/gl/gl_context.h"
#include "render/gl/gl_program.h"
#include "render/image_io.h"
#include "render/output_file.h"
#include "node/config/caps.h"
#include "commands/bench_command.h"
#include "commands/dome_command.h"
#include "commands/ephemeris_command.h"
#include "commands/host_command.h"
#include "commands/precompute_command.h"
#include "commands/probe_command.h"
#include "commands/render_command.h"
#include "commands/replay_command.h"
#include "node/record/recording_source.h"
#include "commands/serve_command.h"
#include "node/transport/udp_socket.h"
#include "node/config/node_config.h"
#include "node/common/stop_signal.h"

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <stdexcept>

int main(int argc, char** argv) {
  using namespace skyig::services;
  // Held until the command that stops on them handles them (node/common/stop_signal.h): a SIGINT
  // 20 ms after start stops a node cleanly instead of killing it.
  holdStopSignals();
  CLI::App app{"skyig — physically based sky image generator for flight simulation"};
  app.require_subcommand(0, 1);
  // Options of the program (--log-level) are accepted after the subcommand too: the
  // subcommands, made below, inherit this and pass what they do not know up.
  app.fallthrough();
  bool version = false, caps = false;
  app.add_flag("--version", version, "Print the build and exit");
  app.add_flag("--caps", caps, "With --version: also the GL renderer, its limits and the transports");
  std::string logLevel = "warn";
  CLI::Option* logLevelOption =
      app.add_option("--log-level", logLevel, "trace, debug, info, warn, error (default: info for serve, else warn)")
          ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error"}));

  int exitCode = 0;
  registerRenderCommand(app, exitCode);
  registerBenchCommand(app, exitCode);
  registerEphemerisCommand(app, exitCode);
  registerServeCommand(app, exitCode);
  registerHostCommand(app, exitCode);
  registerRecordCommand(app, exitCode);
  registerProbeCommand(app, exitCode);
  registerPrecomputeCommand(app, exitCode);
  registerReplayCommand(app, exitCode);
  registerDomeCommand(app, exitCode);

  // Exit codes: 0 done (also when stopped by SIGINT/SIGTERM); 2 bad flags, configuration, input
  // value, output path, or a missing data file (ephemeris/data_files.h); 3 the GPU context or a
  // shader failed, or an output could not be written (a full disk); 4 a socket could not be
  // opened (port in use, no SocketCAN); 1 anything else; 128 + N a second signal N.
  try {
    app.parse_complete_callback([&] {
      // A node says how it started (configuration, channels, transports, renderer) by default.
      if (logLevelOption->count() == 0 && app.got_subcommand("serve")) logLevel = "info";
      spdlog::set_level(spdlog::level::from_str(logLevel));
      // The commands that run until stopped release the signals when they handle them; the
      // others end by them, as any program does.
      bool stopsOnSignal = false;
      for (const char* name : {"serve", "replay", "record", "precompute"}) stopsOnSignal = stopsOnSignal || app.got_subcommand(name);
      if (!stopsOnSignal) releaseStopSignals();
    });
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "skyig: error: %s\n", e.what());
    return 2;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "skyig: error: %s\n", e.what());
    return 2;
  } catch (const skyig::ephemeris::DataFileError& e) {
    std::fprintf(stderr, "skyig: error: %s\n", e.what());
    return 2;
  } catch (const RecordingError& e) {
    std::fprintf(stderr, "skyig: error: %s\n", e.what());
    return 2;
  } catch (const skyig::render::OutputPathError& e) {
    std::fprintf(stderr, "skyig: error: %s\n", e.what());
    return 2;
  } catch (const skyig::render::OutputWriteError& e) {
    std::fprintf(stderr, "skyig: I/O error: %s\n", e.what());
    return 3;
  } catch (const skyig::render::ImageIoError& e) {
    std::fprintf(stderr, "skyig: error: %s\n", e.what());
    return 2;
  } catch (const NetworkError& e) {
    std::fprintf(stderr, "skyig: network error: %s\n", e.what());
    return 4;
  } catch (const skyig::render::GlContextError& e) {
    std::fprintf(stderr, "skyig: GPU error: %s\n", e.what());
    return 3;
  } catch (const skyig::render::ShaderCompileError& e) {
    std::fprintf(stderr, "skyig: shader error: %s\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "skyig: error: %s\n", e.what());
    return 1;
  }
  if (version || caps) {
    std::printf("%s\n", versionText().c_str());
    if (caps) std::printf("%s", capsText().c_str());
    return 0;
  }
  if (app.get_subcommands().empty()) {
    std::printf("%s", app.help().c_str());
    return 0;
  }
  return exitCode;
}
