#pragma once
// Headless rendering. Debian's ParaView renders through X only, so when no X display can be
// opened poresph starts its own Xvfb on a free display number (Xvfb -displayfd), points DISPLAY at
// it and stops it when done: at exit, on error and on SIGINT/SIGTERM (the owner's destructor),
// and with the parent if the parent dies (PR_SET_PDEATHSIG). A ParaView built for EGL or OSMesa
// (ParaView_DIR) needs no display and none is started.
#include <memory>
#include <string>

namespace psph {

class HeadlessDisplay {
 public:
  // Returns an owned Xvfb when one had to be started, nullptr when rendering needs none (a
  // working $DISPLAY, or an EGL/OSMesa ParaView). `note` says what was decided. Throws
  // std::runtime_error when a display is needed and Xvfb cannot be started.
  static std::unique_ptr<HeadlessDisplay> ensure(std::string& note);
  ~HeadlessDisplay();
  HeadlessDisplay(const HeadlessDisplay&) = delete;
  HeadlessDisplay& operator=(const HeadlessDisplay&) = delete;
  const std::string& display() const { return display_; }

 private:
  HeadlessDisplay(int pid, std::string display) : pid_(pid), display_(std::move(display)) {}
  int pid_;
  std::string display_;
};

}  // namespace psph
