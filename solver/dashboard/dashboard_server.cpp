#include "dashboard/dashboard_server.hpp"

#include <httplib.h>

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>


#include "dashboard/run_control.hpp"
#include "dashboard/run_files.hpp"
#include "dashboard/run_status.hpp"
#include "dashboard/run_watcher.hpp"

namespace psph {
namespace fs = std::filesystem;

bool dashboard_available() { return true; }

std::string web_directory() {
  if (const char* env = std::getenv("PORESPH_WEB_DIR")) return env;
#ifdef PORESPH_WEB_DIR
  if (fs::exists(fs::path(PORESPH_WEB_DIR) / "index.html")) return PORESPH_WEB_DIR;
#endif
  return "";
}

namespace {

std::string not_built_page() {
  return "<!doctype html><title>poresph</title><p>This poresph was built without its web front-end "
         "(web/, needs npm at build time). The run's state is at <a href=\"/api/state\">/api/state</a>.</p>";
}

void json_error(httplib::Response& res, int code, const std::string& msg) {
  res.status = code;
  res.set_content(nlohmann::json{{"error", msg}}.dump(), "application/json");
}

}  // namespace

struct DashboardServer::Impl {
  DashboardOptions opt;
  httplib::Server http;
  RunWatcher watcher;
  std::thread serve_thread, poll_thread;
  std::atomic<bool> stopping{false};
  std::atomic<int> streams{0};  // open event streams: the run directory is watched only for them
  std::mutex m;                 // with cv: the poll thread's sleep, stop() waiting for the streams
  std::condition_variable cv;
  int port = 0;

  explicit Impl(const DashboardOptions& o) : opt(o), watcher(o.run_dir) {}
};

DashboardServer::DashboardServer(const DashboardOptions& opt) : impl_(std::make_unique<Impl>(opt)) {
  Impl& d = *impl_;
  if (!fs::is_directory(opt.run_dir)) throw std::runtime_error(opt.run_dir + ": not a run directory");
  const int threads = opt.threads;
  d.http.new_task_queue = [threads] { return new httplib::ThreadPool(static_cast<size_t>(threads)); };
  const std::string web = opt.web_dir.empty() ? web_directory() : opt.web_dir;
  if (web.empty() || !d.http.set_mount_point("/", web))
    d.http.Get("/", [](const httplib::Request&, httplib::Response& res) { res.set_content(not_built_page(), "text/html"); });

  d.http.Get("/api/state", [&d](const httplib::Request&, httplib::Response& res) {
    d.watcher.poll();  // fresh, also when no stream keeps the watcher going
    nlohmann::json s = d.watcher.snapshot();
    s["control"] = !read_run_token(d.opt.run_dir).empty();
    res.set_header("Cache-Control", "no-store");
    res.set_content(s.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), "application/json");
  });

  d.http.Get("/api/events", [&d](const httplib::Request& req, httplib::Response& res) {
    long since = 0;
    try {
      // A reconnecting EventSource says where it stopped; that wins over the page's first ?since.
      if (req.has_header("Last-Event-ID")) since = std::stol(req.get_header_value("Last-Event-ID"));
      else if (req.has_param("since")) since = std::stol(req.get_param_value("since"));
    } catch (const std::exception&) {
      return json_error(res, 400, "since: expected an event number");
    }
    res.set_header("Cache-Control", "no-store");
    auto last = std::make_shared<long>(since);
    d.watcher.poll();
    ++d.streams;
    res.set_chunked_content_provider("text/event-stream", [&d, last](size_t, httplib::DataSink& sink) {
      const bool ending = d.stopping || d.watcher.stopped();
      // Sleeps until an event (or the server's stop) wakes it, at most 15 s: then a comment keeps
      // the connection open through proxies.
      const auto events = d.watcher.events_after(*last, std::chrono::milliseconds(ending ? 0 : 15000));
      std::string out;
      for (const DashboardEvent& e : events) {
        out += "id: " + std::to_string(e.id) + "\nevent: " + e.type + "\ndata: " +
               e.data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n\n";
        *last = e.id;
      }
      if (out.empty() && !ending) out = ": keep-alive\n\n";
      if (!out.empty() && !sink.write(out.data(), out.size())) return false;  // the browser left
      if (ending) sink.done();  // the run's last events are out
      return true;
    }, [&d](bool) {
      --d.streams;
      d.cv.notify_all();
    });
  });

  d.http.Post("/api/control", [&d](const httplib::Request& req, httplib::Response& res) {
    const std::string token = read_run_token(d.opt.run_dir);
    const std::string given = req.get_header_value("X-Poresph-Token");
    if (token.empty()) return json_error(res, 403, "this run takes no control requests (it has no token)");
    unsigned diff = given.size() != token.size();  // compared in constant time
    for (std::size_t k = 0; k < token.size(); ++k) diff |= static_cast<unsigned char>(token[k]) ^ static_cast<unsigned char>(k < given.size() ? given[k] : 0);
    if (diff) return json_error(res, 403, "control needs the run's token in the X-Poresph-Token header");
    ControlRequest r;
    try {
      r = control_request_from_json(nlohmann::json::parse(req.body));
    } catch (const nlohmann::json::exception&) {
      return json_error(res, 400, "expected a JSON body {\"action\": ...}");
    } catch (const std::invalid_argument& e) {
      return json_error(res, 400, e.what());
    }
    d.watcher.poll();
    const nlohmann::json st = d.watcher.snapshot()["status"];
    if (st.is_null() || !status_from_json(st).live())
      return json_error(res, 409, "the run is not running (state " + (st.is_null() ? std::string("unknown") : st["state"].get<std::string>()) + ")");
    const double shortest = cadence_floor(st["dt"].get<double>(), st["end_time"].get<double>());
    for (double v : {r.monitor_interval, r.extract_interval, r.visualisation_interval})
      if (v > 0 && v < shortest)
        return json_error(res, 400, "cadence: an interval of " + std::to_string(v) + " s is shorter than the run allows (" +
                                        std::to_string(shortest) + " s: a time step, and a millionth of the run)");
    try {
      post_control_request(d.opt.run_dir, r);
    } catch (const std::exception& e) {
      return json_error(res, 500, e.what());
    }
    res.status = 202;
    res.set_content(nlohmann::json{{"accepted", to_json(r)}}.dump(), "application/json");
  });

  d.http.Get(R"(/run/(.+))", [&d](const httplib::Request& req, httplib::Response& res) {
    auto f = std::make_shared<RunFile>(d.opt.run_dir, req.matches[1].str());
    if (f->status() == 403) return json_error(res, 403, "not a file of the run's images, extracts or records");
    if (f->status() != 200) return json_error(res, 404, "no such file in the run directory");
    // Streamed in 64 KiB pieces: a large extract never sits whole in the solver's memory.
    res.set_content_provider(static_cast<size_t>(f->size()), f->content_type(),
                             [f](size_t offset, size_t length, httplib::DataSink& sink) {
                               std::vector<char> buf(std::min<size_t>(length, 64 * 1024));
                               const size_t got = f->read(buf.data(), buf.size(), offset);
                               return got > 0 && sink.write(buf.data(), got);
                             });
  });

  d.http.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
    json_error(res, 500, "internal error");
  });
  // On a loopback address, only requests naming it (a page elsewhere that rebinds its own name to
  // 127.0.0.1 cannot read the run or post with a token it saw).
  const bool loopback = opt.bind == "127.0.0.1" || opt.bind == "localhost" || opt.bind == "::1";
  d.http.set_pre_routing_handler([&d, loopback](const httplib::Request& req, httplib::Response& res) {
    if (loopback) {
      const std::string host = req.get_header_value("Host"), port = ":" + std::to_string(d.port);
      if (host != "127.0.0.1" + port && host != "localhost" + port && host != "[::1]" + port) {
        json_error(res, 403, "this dashboard answers to 127.0.0.1" + port + " and localhost" + port + " only");
        return httplib::Server::HandlerResponse::Handled;
      }
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });
  d.http.set_payload_max_length(64 * 1024);
  // cpp-httplib wakes every 10 ms in its accept loop and on idle keep-alive connections, each
  // wake-up a preemption of the solver's threads: block in accept, one request per connection.
  d.http.set_idle_interval(0, 0);
  d.http.set_keep_alive_max_count(1);

  d.watcher.poll();
  if (opt.port == 0) {
    d.port = d.http.bind_to_any_port(opt.bind);
    if (d.port <= 0) throw std::runtime_error("--bind " + opt.bind + ": cannot listen there");
  } else {
    if (!d.http.bind_to_port(opt.bind, opt.port))
      throw std::runtime_error("--serve " + std::to_string(opt.port) + ": cannot listen on " + opt.bind + ":" +
                               std::to_string(opt.port) + " (in use, or not an address of this machine)");
    d.port = opt.port;
  }
  d.serve_thread = std::thread([&d] { d.http.listen_after_bind(); });
  // stop() only stops a server that is listening: wait until it is (bounded).
  for (int k = 0; k < 500 && !d.http.is_running(); ++k) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  d.poll_thread = std::thread([&d] {
    std::unique_lock<std::mutex> lock(d.m);
    while (!d.stopping) {
      d.cv.wait_for(lock, std::chrono::duration<double>(d.opt.poll_period), [&d] { return d.stopping.load(); });
      if (d.streams > 0 && !d.stopping) {
        lock.unlock();
        d.watcher.poll();
        lock.lock();
      }
    }
  });
}

DashboardServer::~DashboardServer() { stop(); }

int DashboardServer::port() const { return impl_->port; }

std::string DashboardServer::url() const {
  const std::string host = impl_->opt.bind == "0.0.0.0" ? "127.0.0.1" : impl_->opt.bind;
  return "http://" + host + ":" + std::to_string(impl_->port) + "/";
}

void DashboardServer::stop() {
  Impl& d = *impl_;
  if (d.stopping.exchange(true)) return;
  d.cv.notify_all();
  d.watcher.poll();  // the run's last words
  d.watcher.stop();  // wakes the event streams, which send what is left and end
  {
    std::unique_lock<std::mutex> lock(d.m);
    d.cv.wait_for(lock, std::chrono::seconds(2), [&d] { return d.streams.load() == 0; });
  }
  d.http.stop();
  if (d.serve_thread.joinable()) d.serve_thread.join();
  if (d.poll_thread.joinable()) d.poll_thread.join();
}

}  // namespace psph
