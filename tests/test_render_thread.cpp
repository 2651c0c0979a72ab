// The render thread's hand-over (catalyst/render_thread.hpp) with a renderer slower than the
// solver: which frames are drawn, which dropped, and where its errors surface. Catalyst itself is
// driven end to end by tests/insitu_tests.cmake; here a renderer that records what it was given
// and takes a fixed time stands in for it, so the policy is checked exactly and without a display.
#include <chrono>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "catalyst/render_thread.hpp"

using namespace psph;

namespace {

struct Recorded {
  std::vector<long> steps;  // the step each rendered frame showed, in order
  std::thread::id thread;   // where it was made, rendered and finalised
  bool same_thread = true, finalised = false;
};

class SlowRenderer final : public InSitu {
 public:
  SlowRenderer(Recorded& r, int ms, long fail_at) : r_(r), ms_(ms), fail_at_(fail_at) { r_.thread = std::this_thread::get_id(); }
  void execute(const ParticleFrame& f, long, double) override {
    r_.same_thread = r_.same_thread && std::this_thread::get_id() == r_.thread;
    std::this_thread::sleep_for(std::chrono::milliseconds(ms_));
    if (f.n == fail_at_) throw std::runtime_error("the pipeline failed at step " + std::to_string(f.n));
    r_.steps.push_back(f.n);
  }
  void finalise() override { r_.finalised = std::this_thread::get_id() == r_.thread; }
  std::string note() const override { return "slow"; }

 private:
  Recorded& r_;
  int ms_;
  long fail_at_;
};

// Hands over `frames` frames (frame k shows step k, in ParticleFrame::n) as fast as it can.
long run(RenderThread& t, int frames) {
  ParticleFrame f;
  for (int k = 0; k < frames; ++k) {
    f.n = k;
    t.submit(f, k, 0.1 * k);
  }
  t.finish();
  return t.dropped();
}

}  // namespace

TEST(RenderThread, TheSolverNeverWaitsAndTheNewestFrameIsDrawn) {
  Recorded r;
  long callbacks = 0;
  RenderThread t([&] { return std::make_unique<SlowRenderer>(r, 40, -1); }, false, 1.0,
                 [&](long, long, double, double) { ++callbacks; });
  const auto t0 = std::chrono::steady_clock::now();
  ParticleFrame f;
  for (int k = 0; k < 20; ++k) f.n = k, t.submit(f, k, 0.1 * k);
  const double handing = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  t.finish();
  EXPECT_LT(handing, 0.2) << "20 hand-overs to a renderer of 40 ms a frame should not wait for it";
  ASSERT_GE(r.steps.size(), 2u);
  EXPECT_EQ(r.steps.front(), 0);
  EXPECT_EQ(r.steps.back(), 19);  // the last frame replaces what waited, never the other way round
  EXPECT_EQ(static_cast<long>(r.steps.size()) + t.dropped(), 20);
  EXPECT_EQ(callbacks, static_cast<long>(r.steps.size()));
  for (std::size_t k = 1; k < r.steps.size(); ++k) EXPECT_GT(r.steps[k], r.steps[k - 1]);
  EXPECT_TRUE(r.same_thread);
  EXPECT_TRUE(r.finalised);
  EXPECT_NE(r.thread, std::this_thread::get_id());
}

TEST(RenderThread, ARendererWithAShareRestsBetweenFrames) {
  // 20 ms frames at a quarter of the wall time: at most one frame per 80 ms while frames keep coming.
  Recorded r;
  RenderThread t([&] { return std::make_unique<SlowRenderer>(r, 20, -1); }, false, 0.25, [](long, long, double, double) {});
  ParticleFrame f;
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < 40; ++k) {
    f.n = k;
    t.submit(f, k, 0.1 * k);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  t.finish();  // draws the last at once, without resting
  // Timed after finish(): a frame may start between the last hand-over and finish() on a busy machine.
  const double span = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(r.steps.back(), 39);
  // One frame per 80 ms, plus two that do not rest: the first (the solver waited for it) and the last.
  EXPECT_LE(static_cast<double>(r.steps.size()), span / 0.08 + 3) << r.steps.size() << " frames in " << span << " s";
  EXPECT_GE(r.steps.size(), 3u);
}

TEST(RenderThread, EveryFrameWaitsForRoom) {
  Recorded r;
  RenderThread t([&] { return std::make_unique<SlowRenderer>(r, 5, -1); }, true, 0.05, [](long, long, double, double) {});
  EXPECT_EQ(run(t, 12), 0);
  ASSERT_EQ(r.steps.size(), 12u);
  for (long k = 0; k < 12; ++k) EXPECT_EQ(r.steps[k], k);
  EXPECT_GT(t.waited_seconds(), 0.0);
}

TEST(RenderThread, ARendererErrorReachesTheSolver) {
  Recorded r;
  RenderThread t([&] { return std::make_unique<SlowRenderer>(r, 1, 0); }, true, 1.0, [](long, long, double, double) {});
  ParticleFrame f;
  f.n = 0;
  t.submit(f, 0, 0.0);
  try {
    for (int k = 1; k < 100; ++k) f.n = k, t.submit(f, k, 0.1 * k);  // waits for room, then sees the error
    t.finish();
    FAIL() << "the renderer's error was not rethrown";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "the pipeline failed at step 0");
  }
  EXPECT_THROW(t.finish(), std::runtime_error);  // and again at the end
  EXPECT_THROW(RenderThread([]() -> std::unique_ptr<InSitu> { throw std::runtime_error("no script"); }, false, 1.0,
                            [](long, long, double, double) {}),
               std::runtime_error);
}
