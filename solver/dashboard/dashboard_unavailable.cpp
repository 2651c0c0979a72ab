// A build without cpp-httplib: no dashboard server (the run still writes status.json and takes
// control requests, so `poresph serve` from a full build can attach to it).
#include <stdexcept>

#include "dashboard/dashboard_server.hpp"

namespace psph {

bool dashboard_available() { return false; }
std::string web_directory() { return ""; }

struct DashboardServer::Impl {};

DashboardServer::DashboardServer(const DashboardOptions&) {
  throw std::runtime_error("this poresph was built without the dashboard (cpp-httplib not found: apt-get install libcpp-httplib-dev)");
}
DashboardServer::~DashboardServer() = default;
int DashboardServer::port() const { return 0; }
std::string DashboardServer::url() const { return ""; }
void DashboardServer::stop() {}

}  // namespace psph
