// serve's windows on a real X server (Xvfb, started by the test on a display number of its own):
// every window, read back from the X server by its title after a frame, shows the frame the
// headless renderer draws for the same state, attitude and channel, for 1, 3 and 5 windows.
// This is what the projectors receive: the right channel in the right window, nothing lost or
// swapped by presenting every window in one frame with a single vsync'd swap.
#include "render/gl/swap_group.h"
#include "calibration/load.h"
#include "node/frame/display_outputs.h"
#include "node/node.h"
#include "node/transport/udp_socket.h"
#include "protocol/cigi/encoder.h"
#include "tests/node/window_ring.h"
#include "tests/virtual_x.h"

#include <gtest/gtest.h>

#include <atomic>
#include <bit>
#include <thread>
#include <cstdlib>
#include <map>
#include <optional>
#include <string>
#include <vector>

// Last: Xlib's macros (None, Bool, Status) would rename gtest's and skyig's identifiers.
#include <X11/Xlib.h>
#include <X11/Xutil.h>

namespace {

using namespace skyig;

using skyig::testing::VirtualX;

VirtualX* gX = nullptr;

// The top-level windows' pixels as the X server holds them, by title: RGB, top row first.
class XScreenshots {
 public:
  XScreenshots() : x_(XOpenDisplay(nullptr)) {}
  ~XScreenshots() {
    if (x_) XCloseDisplay(x_);
  }
  bool open() const { return x_ != nullptr; }

  std::optional<std::vector<std::uint8_t>> grab(const std::string& title, int width, int height) {
    XSync(x_, False);
    const Window w = find(DefaultRootWindow(x_), title);
    if (!w) return std::nullopt;
    return read(w, width, height);
  }
  // A window's size on the X server, by title.
  std::optional<std::pair<int, int>> size(const std::string& title) {
    XSync(x_, False);
    const Window w = find(DefaultRootWindow(x_), title);
    XWindowAttributes a;
    if (!w || !XGetWindowAttributes(x_, w, &a)) return std::nullopt;
    return std::pair{a.width, a.height};
  }
  std::optional<std::vector<std::uint8_t>> grabRoot(int width, int height) {
    XSync(x_, False);
    return read(DefaultRootWindow(x_), width, height);
  }

 private:
  std::optional<std::vector<std::uint8_t>> read(Window w, int width, int height) {
    XImage* image = XGetImage(x_, w, 0, 0, static_cast<unsigned>(width), static_cast<unsigned>(height), AllPlanes, ZPixmap);
    if (!image) return std::nullopt;
    std::vector<std::uint8_t> rgb;
    rgb.reserve(static_cast<std::size_t>(width) * height * 3);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const unsigned long p = XGetPixel(image, x, y);
        for (unsigned long mask : {image->red_mask, image->green_mask, image->blue_mask})
          rgb.push_back(static_cast<std::uint8_t>((p & mask) >> std::countr_zero(mask)));
      }
    XDestroyImage(image);
    return rgb;
  }

  Window find(Window parent, const std::string& title) {
    Window root = 0, up = 0, *children = nullptr;
    unsigned count = 0;
    if (!XQueryTree(x_, parent, &root, &up, &children, &count)) return 0;
    Window found = 0;
    for (unsigned i = 0; i < count && !found; ++i) {
      char* name = nullptr;
      if (XFetchName(x_, children[i], &name) && name) {
        if (title == name) found = children[i];
        XFree(name);
      }
      if (!found) found = find(children[i], title);
    }
    if (children) XFree(children);
    return found;
  }

  Display* x_;
};

std::vector<sky::ChannelConfig> ring(int n) { return services::testing::windowRing(n, 64, 48); }

class WindowScreenshots : public ::testing::TestWithParam<int> {
 protected:
  static void SetUpTestSuite() {
    gX = new VirtualX;
    if (!gX->display().empty()) ::setenv("DISPLAY", gX->display().c_str(), 1);
  }
  static void TearDownTestSuite() {
    delete gX;
    gX = nullptr;
  }
};

// The headless frames of `channels` (what `skyig render` and --save-frames write), by name.
std::map<std::string, render::DisplayImage> headlessFrames(const std::vector<sky::ChannelConfig>& channels,
                                                           const sky::SkyState& state, const sky::Attitude& attitude) {
  std::map<std::string, render::DisplayImage> frames;
  services::DisplayOutputs headless(true, "test", channels);
  headless.draw(state, attitude, channels,
                [&](const render::SkyRenderer& r, const sky::ChannelConfig& c, const calibration::ProjectorCalibration*) { frames[c.name] = r.readDisplay(); });
  return frames;
}

TEST_P(WindowScreenshots, EveryWindowShowsTheHeadlessFrameOfItsChannel) {
  ASSERT_FALSE(gX->display().empty()) << "Xvfb did not start (deploy/setup.sh installs it)";
  const std::vector<sky::ChannelConfig> channels = ring(GetParam());
  sky::ObserverState observer;
  observer.attitude = {20.0, 3.0, 0.0};
  const sky::SkyState state = sky::buildSkyState(observer, sky::SkyConditions{}, sky::SunOverride{60.0, 8.0});

  const std::map<std::string, render::DisplayImage> expected = headlessFrames(channels, state, observer.attitude);

  services::DisplayOutputs windows(false, "test", channels);
  const std::vector<std::string> titles = windows.windowTitles();
  ASSERT_EQ(titles.size(), channels.size());
  // Every window in swap group 1 where the driver offers it (not Mesa's GLX under Xvfb), else none.
  EXPECT_EQ(windows.swapGroupMembers(), render::querySwapGroupSupport().available ? channels.size() : 0u);
  XScreenshots x;
  ASSERT_TRUE(x.open());
  for (int frame = 0; frame < 3; ++frame) windows.draw(state, observer.attitude, channels);

  for (std::size_t i = 0; i < channels.size(); ++i) {
    const sky::ChannelConfig& c = channels[i];
    const auto shown = x.grab(titles[i], c.width, c.height);
    ASSERT_TRUE(shown) << "no window titled \"" << titles[i] << "\" on " << gX->display();
    const render::DisplayImage& want = expected.at(c.name);
    ASSERT_EQ(want.width, c.width);
    int worst = 0;
    double sum = 0.0;
    for (int y = 0; y < c.height; ++y)
      for (int px = 0; px < c.width; ++px)
        for (int k = 0; k < 3; ++k) {
          const int a = (*shown)[(static_cast<std::size_t>(y) * c.width + px) * 3 + k];
          const int b = want.rgba[(static_cast<std::size_t>(y) * c.width + px) * 4 + k];
          worst = std::max(worst, std::abs(a - b));
          sum += b;
        }
    EXPECT_LE(worst, 1) << "window " << titles[i] << " differs from the headless frame by " << worst << " codes";
    EXPECT_GT(sum / (c.width * c.height * 3), 20.0) << c.name << ": the headless frame is dark, the test shows nothing";
  }
  // The channels differ from one another (a window showing another channel's frame would fail above).
  if (channels.size() > 1) {
    EXPECT_NE(expected.at("c0").rgba, expected.at("c1").rgba);
  }
}

// A projector's window is what the projector is sent: the generated dome's left and centre
// projectors (tests/data/calibration/dome5_small.mpcdi, 160x100), warped and blended, show in
// their windows as the headless render sends them, at the projector's size.
TEST_F(WindowScreenshots, ProjectorWindowsShowWhatTheProjectorsAreSent) {
  ASSERT_FALSE(gX->display().empty()) << "Xvfb did not start (deploy/setup.sh installs it)";
  const std::string dome = std::string(SKYIG_SOURCE_DIR) + "/tests/data/calibration/dome5_small.mpcdi";
  std::vector<sky::ChannelConfig> channels;
  std::vector<services::DisplayOutputs::Projector> projectors;
  for (const char* region : {"left", "centre"}) {
    auto p = std::make_shared<const calibration::ProjectorCalibration>(calibration::loadProjector(calibration::mpcdiSource(dome, region)));
    sky::ChannelConfig c;
    c.name = region;
    c.offset = p->camera.offset;
    c.frustum = p->camera.frustum;
    c.width = 96;  // the channel renders smaller than its projector: the warp resamples it
    c.height = 64;
    channels.push_back(c);
    projectors.push_back(p);
  }
  sky::ObserverState observer;
  observer.attitude = {20.0, 0.0, 0.0};
  const sky::SkyState state = sky::buildSkyState(observer, sky::SkyConditions{}, sky::SunOverride{40.0, 10.0});
  std::map<std::string, render::DisplayImage> expected;
  {
    services::DisplayOutputs headless(true, "test", channels, projectors);
    headless.draw(state, observer.attitude, channels,
                  [&](const render::SkyRenderer& r, const sky::ChannelConfig& c, const calibration::ProjectorCalibration* p) {
                    ASSERT_NE(p, nullptr);
                    expected[c.name] = r.readProjectorDisplay();
                  });
  }
  services::DisplayOutputs windows(false, "test", channels, projectors);
  const std::vector<std::string> titles = windows.windowTitles();
  XScreenshots x;
  ASSERT_TRUE(x.open());
  for (int frame = 0; frame < 3; ++frame) windows.draw(state, observer.attitude, channels);
  for (std::size_t i = 0; i < channels.size(); ++i) {
    const render::DisplayImage& want = expected.at(channels[i].name);
    ASSERT_EQ(want.width, 160);
    ASSERT_EQ(want.height, 100);
    const auto shown = x.grab(titles[i], want.width, want.height);
    ASSERT_TRUE(shown) << "no window titled \"" << titles[i] << "\"";
    int worst = 0;
    double sum = 0.0;
    for (int y = 0; y < want.height; ++y)
      for (int px = 0; px < want.width; ++px)
        for (int k = 0; k < 3; ++k) {
          const int a = (*shown)[(static_cast<std::size_t>(y) * want.width + px) * 3 + k];
          const int b = want.rgba[(static_cast<std::size_t>(y) * want.width + px) * 4 + k];
          worst = std::max(worst, std::abs(a - b));
          sum += b;
        }
    EXPECT_LE(worst, 1) << titles[i] << " differs from what the projector is sent by " << worst << " codes";
    EXPECT_GT(sum / (want.width * want.height * 3), 20.0) << titles[i] << ": the projector image is dark";
  }
}

// A channel with `monitor` is fullscreen on that monitor: Xvfb's one monitor, 1024x256, shows the
// channel's frame over the whole screen; a name no monitor has is refused before anything renders.
// A node that cannot hold its rate draws its channels smaller (node/frame/degradation.h): each
// window still shows its whole channel, stretched, not a quarter of it in a corner: against the
// full-size headless frame, the mean difference is that of a bilinear upsample.
TEST_F(WindowScreenshots, AChannelDrawnAtHalfSizeFillsItsWindow) {
  ASSERT_FALSE(gX->display().empty()) << "Xvfb did not start (deploy/setup.sh installs it)";
  const std::vector<sky::ChannelConfig> channels = ring(2);
  sky::ObserverState observer;
  observer.attitude = {20.0, 3.0, 0.0};
  const sky::SkyState state = sky::buildSkyState(observer, sky::SkyConditions{}, sky::SunOverride{60.0, 8.0});
  const std::map<std::string, render::DisplayImage> full = headlessFrames(channels, state, observer.attitude);
  std::vector<sky::ChannelConfig> half = channels;
  for (auto& c : half) {
    c.width /= 2;
    c.height /= 2;
  }
  services::DisplayOutputs windows(false, "test", channels);
  XScreenshots x;
  ASSERT_TRUE(x.open());
  for (int frame = 0; frame < 3; ++frame) windows.draw(state, observer.attitude, half);
  for (std::size_t i = 0; i < channels.size(); ++i) {
    const sky::ChannelConfig& c = channels[i];
    const auto shown = x.grab(windows.windowTitles()[i], c.width, c.height);
    ASSERT_TRUE(shown);
    const render::DisplayImage& want = full.at(c.name);
    double sum = 0.0, corner = 0.0;
    for (int y = 0; y < c.height; ++y)
      for (int px = 0; px < c.width; ++px)
        for (int k = 0; k < 3; ++k) {
          const int a = (*shown)[(static_cast<std::size_t>(y) * c.width + px) * 3 + k];
          sum += std::abs(a - want.rgba[(static_cast<std::size_t>(y) * c.width + px) * 4 + k]);
          if (y < c.height / 2 && px >= c.width / 2) corner += a;  // the top right: empty if not stretched
        }
    const double mean = sum / (c.width * c.height * 3.0);
    std::printf("%s at half size in its window: mean difference %.2f codes from the full-size frame\n", c.name.c_str(), mean);
    EXPECT_LT(mean, 3.0) << c.name;
    EXPECT_GT(corner / (c.width * c.height * 3 / 4.0), 20.0) << c.name << ": the window's top right is dark";
  }
}

// A slow windowed dome (three windows, every frame over a 1 ms period) still answers the host
// with a Start of Frame for every frame it draws, as the CIGI ICD asks in asynchronous mode.
TEST_F(WindowScreenshots, ASlowWindowedNodeSendsAStartOfFrameForEveryFrame) {
  ASSERT_FALSE(gX->display().empty()) << "Xvfb did not start (deploy/setup.sh installs it)";
  services::UdpSocket host({"127.0.0.1", 0});
  services::NodeOptions o;
  o.config.sky.model = sky::SkyModel::Preetham;
  o.config.channels = ring(3);
  o.config.channelNodes = {"", "", ""};
  o.config.channelProjectors = {{}, {}, {}};
  o.listen = {"127.0.0.1", services::UdpSocket({"127.0.0.1", 0}).localEndpoint().port};  // a free port
  o.replyPort = host.localEndpoint().port;
  o.headless = false;
  o.frames = 30;
  o.frameRateHz = 1000.0;
  o.logIntervalS = 0.0;
  std::atomic<bool> hostStop{false};
  std::thread hostThread([&] {  // 30 Hz of IG Control, from before the node listens until it is done
    const sockaddr_in to = services::toSockaddr(o.listen);
    for (std::uint32_t frame = 1; !hostStop; ++frame) {
      protocol::cigi::IgControl ig;
      ig.hostFrameNumber = frame;
      const protocol::cigi::Packet packets[] = {ig};
      std::vector<std::uint8_t> bytes;
      if (protocol::cigi::encodeMessage(packets, protocol::ByteOrder::big, bytes).empty()) host.sendTo(bytes, to);
      std::this_thread::sleep_for(std::chrono::milliseconds(33));
    }
  });
  services::NodeStats stats;
  std::atomic<bool> stop{false};
  int code = -1;
  try {
    code = services::runNode(o, stats, stop);
  } catch (const std::exception& e) {
    ADD_FAILURE() << e.what();
  }
  hostStop = true;
  hostThread.join();
  EXPECT_EQ(code, 0);
  EXPECT_EQ(stats.frames.load(), 30u);
  EXPECT_EQ(stats.startOfFrameSent.load(), stats.frames.load()) << "frames over the period: " << stats.framesOverPeriod.load();
  EXPECT_GT(stats.framesOverPeriod.load(), 0u) << "the node was meant to be slow";
}

TEST_F(WindowScreenshots, ChannelWithAMonitorIsFullscreenOnIt) {
  ASSERT_FALSE(gX->display().empty()) << "Xvfb did not start (deploy/setup.sh installs it)";
  const std::vector<std::string> monitors = render::monitorNames();
  ASSERT_EQ(monitors.size(), 1u) << "Xvfb with one screen has one monitor";
  std::vector<sky::ChannelConfig> channels = ring(1);
  channels[0].width = 1024;
  channels[0].height = 256;
  channels[0].frustum = {60.0, 60.0, 5.0, 25.0};
  channels[0].monitor = "no such monitor";
  try {
    services::DisplayOutputs refused(false, "test", channels);
    ADD_FAILURE() << "a monitor no one has was accepted";
  } catch (const render::GlContextError& e) {
    EXPECT_NE(std::string(e.what()).find("'" + monitors.front() + "'"), std::string::npos) << e.what();  // names the ones there are
  }
  channels[0].monitor = monitors.front();

  sky::ObserverState observer;
  const sky::SkyState state = sky::buildSkyState(observer, sky::SkyConditions{}, sky::SunOverride{60.0, 8.0});
  render::DisplayImage want;
  {
    services::DisplayOutputs headless(true, "test", channels);
    headless.draw(state, observer.attitude, channels,
                  [&](const render::SkyRenderer& r, const sky::ChannelConfig&, const calibration::ProjectorCalibration*) { want = r.readDisplay(); });
  }
  services::DisplayOutputs windows(false, "test", channels);
  for (int frame = 0; frame < 2; ++frame) windows.draw(state, observer.attitude, channels);
  XScreenshots x;
  ASSERT_TRUE(x.open());
  EXPECT_EQ(x.size(windows.windowTitles().front()), (std::pair{1024, 256}));
  const auto shown = x.grabRoot(1024, 256);  // the whole screen, not just the window
  ASSERT_TRUE(shown);
  int worst = 0;
  for (std::size_t p = 0; p < shown->size(); ++p)
    worst = std::max(worst, std::abs(int{(*shown)[p]} - int{want.rgba[p / 3 * 4 + p % 3]}));
  EXPECT_LE(worst, 1) << "the screen differs from the headless frame by " << worst << " codes";
}

// Fullscreen takes the monitor's mode whatever the channel's size (Xvfb has one, its screen's):
// a 320x80 channel's window covers the 1024x256 screen, a windowed one is 320x80.
TEST_F(WindowScreenshots, FullscreenWindowCoversItsMonitor) {
  ASSERT_FALSE(gX->display().empty()) << "Xvfb did not start (deploy/setup.sh installs it)";
  std::vector<sky::ChannelConfig> channels = ring(2);
  for (auto& c : channels) {
    c.width = 320;
    c.height = 80;
  }
  channels[1].monitor = render::monitorNames().front();
  services::DisplayOutputs windows(false, "test", channels);
  XScreenshots x;
  ASSERT_TRUE(x.open());
  EXPECT_EQ(x.size(windows.windowTitles()[0]), (std::pair{320, 80}));
  EXPECT_EQ(x.size(windows.windowTitles()[1]), (std::pair{1024, 256}));
}

INSTANTIATE_TEST_SUITE_P(Outputs, WindowScreenshots, ::testing::Values(1, 3, 5),
                         [](const ::testing::TestParamInfo<int>& p) { return std::to_string(p.param) + "Windows"; });

}  // namespace
