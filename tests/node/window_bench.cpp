// Frames per second of serve's outputs at N = 1, 3 and 5 channels of 160x120: in windows
// (every channel drawn and fenced, one vsync'd swap; needs an X display, e.g.
// `xvfb-run -a -s "-screen 0 1024x256x24" build/tests/node/window_bench`) and headless
// (the same draws without windows), so the cost of presenting shows as their difference;
// present_ms is the windows' fence wait and swaps alone.
// Figures: docs/performance.md, "Presentation".
#include "node/frame/display_outputs.h"
#include "tests/node/window_ring.h"

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace {

using namespace skyig;

std::vector<sky::ChannelConfig> ring(int n) { return services::testing::windowRing(n, 160, 120); }

void frames(benchmark::State& s, bool headless) {
  if (!headless && !std::getenv("DISPLAY")) {
    s.SkipWithError("no X display: run under xvfb-run");
    return;
  }
  const auto channels = ring(static_cast<int>(s.range(0)));
  sky::ObserverState observer;
  const sky::SkyState state = sky::buildSkyState(observer, sky::SkyConditions{}, sky::SunOverride{60.0, 8.0});
  services::DisplayOutputs outputs(headless, "bench", channels);
  for (int i = 0; i < 3; ++i) outputs.draw(state, observer.attitude, channels);  // programs compiled, tables up
  double presentS = 0.0;
  for (auto _ : s) {
    outputs.draw(state, observer.attitude, channels);
    presentS += outputs.lastPresentSeconds();
  }
  s.counters["present_ms"] = 1e3 * presentS / static_cast<double>(s.iterations());
  s.counters["fps"] = benchmark::Counter(static_cast<double>(s.iterations()), benchmark::Counter::kIsRate);
}

void BM_WindowsFrame(benchmark::State& s) { frames(s, false); }
void BM_HeadlessFrame(benchmark::State& s) { frames(s, true); }

BENCHMARK(BM_WindowsFrame)->Arg(1)->Arg(3)->Arg(5)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HeadlessFrame)->Arg(1)->Arg(3)->Arg(5)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
