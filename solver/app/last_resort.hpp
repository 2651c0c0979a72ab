#pragma once
// The last resort: an exception that no command caught, in any thread, is an internal error: the
// message and exit 4, never an abort with a core dump. A file-size limit (ulimit -f) fails a write
// with EFBIG, which the run reports (exit 5), instead of killing the process with SIGXFSZ.
#include <csignal>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

namespace psph {

[[noreturn]] inline void internal_error() {
  std::string what = "an unknown exception";
  if (const std::exception_ptr e = std::current_exception()) try {
      std::rethrow_exception(e);
    } catch (const std::exception& x) {
      what = x.what();
    } catch (...) {
    }
  std::cerr << "poresph: internal error: " << what << std::endl;
  std::_Exit(4);
}

inline void install_last_resort() {
  std::set_terminate(internal_error);
  std::signal(SIGXFSZ, SIG_IGN);
}

}  // namespace psph
