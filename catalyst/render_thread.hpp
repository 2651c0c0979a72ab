#pragma once
// In-situ rendering off the solver's critical path: one thread owns the in-situ implementation
// (Catalyst's Python, its pipelines and GL context live and die on it) and renders staged frames
// while the solver steps on. Double-buffered: one frame rendering, at most one waiting. A frame
// handed over while one is still waiting replaces it (the waiting one is dropped and counted), so
// the newest state is always the next drawn and the solver never waits for the renderer, unless
// `every_frame` asks it to wait for room instead. The first frame is drawn while the solver waits
// (it builds the pipelines). Where the
// renderer and the solver share the cores (a CPU run: llvmpipe renders on the CPU too), the
// renderer rests after each frame so that it takes at most `share` of the wall time: measured on
// 2 cores, at a lower priority it still cost the solver 17 % of its step rate (its threads
// preempt an OpenMP team, whose other threads then wait at the barrier), and at idle priority it
// never ran while the solver did.
#include <condition_variable>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "catalyst/insitu.hpp"

namespace psph {

class RenderThread {
 public:
  // Called on the render thread once a frame's outputs are written: its number among the rendered
  // frames, the step and time it shows, and the seconds it took.
  using Rendered = std::function<void(long frame, long step, double time, double seconds)>;

  // Starts the thread and waits until `make` has returned there; rethrows what it threw.
  // `share` in (0, 1]: the most of the wall time the renderer takes (1: no rest; every_frame: none).
  RenderThread(std::function<std::unique_ptr<InSitu>()> make, bool every_frame, double share, Rendered rendered);
  ~RenderThread();
  const std::string& note() const { return note_; }

  // Hands `frame` over by swapping buffers (`frame` gets back a free one to stage into).
  // Rethrows the renderer's first error.
  void submit(ParticleFrame& frame, long step, double time);
  // Renders what waits, ends the pipelines and the thread; rethrows the renderer's first error.
  void finish();
  long dropped() const;
  double waited_seconds() const { return waited_s_; }    // the solver's time blocked in submit
  double drained_seconds() const { return drained_s_; }  // in finish, for the frames left to render

 private:
  void run(const std::function<std::unique_ptr<InSitu>()>& make);
  void rethrow_locked();

  const bool every_frame_;
  const double share_;
  Rendered rendered_;
  std::string note_;
  mutable std::mutex m_;
  std::condition_variable cv_;
  ParticleFrame waiting_;
  bool has_waiting_ = false, started_ = false, stopping_ = false;
  long step_ = 0, dropped_ = 0, submitted_ = 0, drawn_ = 0;
  double time_ = 0, waited_s_ = 0, drained_s_ = 0;
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace psph
