#include "catalyst/render_thread.hpp"

#include <algorithm>
#include <chrono>
#include <utility>

namespace psph {
namespace {

using clock = std::chrono::steady_clock;
double seconds_since(clock::time_point t0) { return std::chrono::duration<double>(clock::now() - t0).count(); }

}  // namespace

RenderThread::RenderThread(std::function<std::unique_ptr<InSitu>()> make, bool every_frame, double share,
                           Rendered rendered)
    : every_frame_(every_frame), share_(std::clamp(share, 0.01, 1.0)), rendered_(std::move(rendered)) {
  thread_ = std::thread([this, make] { run(make); });
  std::unique_lock<std::mutex> lock(m_);
  cv_.wait(lock, [&] { return started_; });
  if (error_) {
    lock.unlock();
    thread_.join();
    std::rethrow_exception(error_);
  }
}

RenderThread::~RenderThread() {
  try {
    finish();
  } catch (...) {  // reported by an earlier finish() or submit(); a destructor does not throw
  }
}

void RenderThread::run(const std::function<std::unique_ptr<InSitu>()>& make) {
  std::unique_ptr<InSitu> insitu;
  {
    std::lock_guard<std::mutex> lock(m_);
    try {
      insitu = make();
      note_ = insitu->note();
    } catch (...) {
      error_ = std::current_exception();
    }
    started_ = true;
  }
  cv_.notify_all();
  if (!insitu) return;
  ParticleFrame frame;
  for (long n = 0;; ++n) {
    long step;
    double time;
    {
      std::unique_lock<std::mutex> lock(m_);
      cv_.wait(lock, [&] { return has_waiting_ || stopping_; });
      if (!has_waiting_) break;
      std::swap(frame, waiting_);
      has_waiting_ = false, step = step_, time = time_;
    }
    cv_.notify_all();
    const auto t0 = clock::now();
    try {
      if (!error_) insitu->execute(frame, n, time), rendered_(n, step, time, seconds_since(t0));
    } catch (...) {
      std::lock_guard<std::mutex> lock(m_);
      error_ = std::current_exception();
    }
    std::unique_lock<std::mutex> lock(m_);
    ++drawn_;
    cv_.notify_all();  // a waiting submit sees the frame drawn, or the error
    // Rest for (1/share - 1) times the frame's time, so that rendering takes at most `share` of
    // the wall time from the cores the solver uses; finish() cuts the rest short. Not after the
    // first frame, for which the solver waited.
    const double rest = every_frame_ || n == 0 ? 0 : seconds_since(t0) * (1 / share_ - 1);
    cv_.wait_for(lock, std::chrono::duration<double>(rest), [&] { return stopping_; });
  }
  try {
    insitu->finalise();
    insitu.reset();  // Catalyst ends on the thread it started on
  } catch (...) {
    std::lock_guard<std::mutex> lock(m_);
    if (!error_) error_ = std::current_exception();
  }
}

void RenderThread::rethrow_locked() {
  if (error_) std::rethrow_exception(error_);
}

void RenderThread::submit(ParticleFrame& frame, long step, double time) {
  const auto t0 = clock::now();
  std::unique_lock<std::mutex> lock(m_);
  rethrow_locked();
  if (every_frame_) cv_.wait(lock, [&] { return !has_waiting_ || error_; });
  rethrow_locked();
  if (has_waiting_) ++dropped_;
  std::swap(frame, waiting_);
  has_waiting_ = true, step_ = step, time_ = time;
  cv_.notify_all();
  // The first frame is drawn while the solver waits: it builds the pipelines (seconds of Python
  // and VTK), which beside the solver would slow a short run by a third (measured on 2 cores).
  if (submitted_++ == 0) cv_.wait(lock, [&] { return drawn_ > 0 || error_; });
  waited_s_ += seconds_since(t0);
}

void RenderThread::finish() {
  if (!thread_.joinable()) {
    std::lock_guard<std::mutex> lock(m_);
    return rethrow_locked();
  }
  const auto t0 = clock::now();
  {
    std::lock_guard<std::mutex> lock(m_);
    stopping_ = true;
  }
  cv_.notify_all();
  thread_.join();
  std::lock_guard<std::mutex> lock(m_);
  drained_s_ += seconds_since(t0);
  rethrow_locked();
}

long RenderThread::dropped() const {
  std::lock_guard<std::mutex> lock(m_);
  return dropped_;
}

}  // namespace psph
