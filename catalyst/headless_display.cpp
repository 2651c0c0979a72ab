#include "catalyst/headless_display.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <stdexcept>

#include <X11/Xlib.h>
#include <vtkRenderingOpenGLConfigure.h>

namespace psph {
namespace {

bool display_works() {
  const char* d = std::getenv("DISPLAY");
  if (!d || !*d) return false;
  Display* x = XOpenDisplay(d);
  if (!x) return false;
  XCloseDisplay(x);
  return true;
}

}  // namespace

std::unique_ptr<HeadlessDisplay> HeadlessDisplay::ensure(std::string& note) {
#if defined(VTK_OPENGL_HAS_EGL) || defined(VTK_OPENGL_HAS_OSMESA)
  note = "ParaView renders off-screen (EGL/OSMesa): no X display needed";
  return nullptr;
#else
  if (display_works()) {
    note = std::string("rendering on X display ") + std::getenv("DISPLAY");
    return nullptr;
  }
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("cannot start Xvfb: pipe() failed");
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("cannot start Xvfb: fork() failed");
  if (pid == 0) {
    prctl(PR_SET_PDEATHSIG, SIGTERM);  // never outlive poresph
    setpgid(0, 0);                     // a terminal's Ctrl-C goes to poresph, which then stops Xvfb
    close(fds[0]);
    const int null = open("/dev/null", O_RDWR);
    dup2(null, 0), dup2(null, 1), dup2(null, 2);
    const std::string fd = std::to_string(fds[1]);
    execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1280x1024x24", "-noreset", "-nolisten", "tcp",
           static_cast<char*>(nullptr));
    _exit(127);
  }
  close(fds[1]);
  std::string number;
  pollfd p{fds[0], POLLIN, 0};
  char c;
  while (poll(&p, 1, 20000) > 0 && read(fds[0], &c, 1) == 1 && c != '\n') number += c;
  close(fds[0]);
  if (number.empty()) {
    kill(pid, SIGTERM);
    waitpid(pid, nullptr, 0);
    throw std::runtime_error(
        "rendering needs an X display and none is set; starting Xvfb failed (install it with "
        "scripts/install-deps.sh or apt-get install xvfb, or set DISPLAY)");
  }
  const std::string display = ":" + number;
  setenv("DISPLAY", display.c_str(), 1);
  note = "no X display: started Xvfb on " + display + " (stopped at exit)";
  return std::unique_ptr<HeadlessDisplay>(new HeadlessDisplay(pid, display));
#endif
}

HeadlessDisplay::~HeadlessDisplay() {
  kill(pid_, SIGTERM);
  waitpid(pid_, nullptr, 0);
  unsetenv("DISPLAY");
}

}  // namespace psph
