// poresph serve RUNDIR: the dashboard of a finished run, or of one still running in another
// process (it reads the run directory, and posts control requests there with the run's token).
#include <chrono>
#include <filesystem>
#include <iostream>
#include <thread>

#include "app/commands.hpp"
#include "app/interrupts.hpp"
#include "dashboard/dashboard_server.hpp"
#include "dashboard/run_control.hpp"

namespace psph {
int cmd_serve(const std::string& run_dir, int port, const std::string& bind) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(run_dir) || !fs::exists(fs::path(run_dir) / "case.resolved.toml")) {
    std::cerr << "poresph: serve " << run_dir << ": not a run directory (expected case.resolved.toml in it)\n";
    return 2;
  }
  std::unique_ptr<DashboardServer> server;
  try {
    server = std::make_unique<DashboardServer>(DashboardOptions{run_dir, "", bind, port});
  } catch (const std::exception& e) {
    std::cerr << "poresph: serve: " << e.what() << "\n";
    return 2;
  }
  const std::string token = read_run_token(run_dir);
  std::cout << "poresph serve " << run_dir << ": dashboard at " << server->url()
            << (token.empty() ? "" : "?token=" + token) << " (Ctrl-C to stop)" << std::endl;
  catch_interrupts();
  while (!caught_interrupt()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  server->stop();
  release_interrupts();
  return 0;
}

}  // namespace psph
