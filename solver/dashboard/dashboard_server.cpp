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


#include "dashboard/accepted_sockets.hpp"
#include "dashboard/request_gate.hpp"
#include "dashboard/run_control.hpp"
#include "dashboard/run_files.hpp"
#include "dashboard/run_status.hpp"
#include "dashboard/run_watcher.hpp"
#include "dashboard/stream_slots.hpp"

#include <sys/socket.h>

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

// Where a page's event stream is: the last event sent, its connection, when it last sent.
struct StreamCursor {
  long last = 0;
  int socket = -1;
  std::chrono::steady_clock::time_point sent = std::chrono::steady_clock::now();
};

void json_error(httplib::Response& res, int code, const std::string& msg) {
  res.status = code;
  res.set_content(nlohmann::json{{"error", msg}}.dump(), "application/json");
}

}  // namespace

struct DashboardServer::Impl {
  DashboardOptions opt;
  httplib::Server http;
  RunWatcher watcher;
  StreamSlots slots;
  std::thread serve_thread, poll_thread;
  std::atomic<bool> stopping{false};
  std::atomic<int> streams{0};  // open event streams: the run directory is watched only for them
  std::mutex m;                 // with cv: the poll thread's sleep, stop() waiting for the streams
  std::condition_variable cv;
  int port = 0, listener = -1;

  explicit Impl(const DashboardOptions& o) : opt(o), watcher(o.run_dir), slots(o.max_streams, o.max_streams_per_client) {}
  bool send_events(StreamCursor& c, httplib::DataSink& sink);
};

// Sleeps until an event (or the server's stop) wakes it, at most a second: then looks whether the
// page has gone (its stream's slot is free again within a second of a closed tab), and every 15 s
// sends a comment that keeps the connection open through proxies. False: the page has gone.
bool DashboardServer::Impl::send_events(StreamCursor& c, httplib::DataSink& sink) {
  const bool ending = stopping || watcher.stopped();
  const auto events = watcher.events_after(c.last, std::chrono::milliseconds(ending ? 0 : 1000));
  std::string out;
  for (const DashboardEvent& e : events) {
    out += "id: " + std::to_string(e.id) + "\nevent: " + e.type + "\ndata: " +
           e.data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n\n";
    c.last = e.id;
  }
  const auto now = std::chrono::steady_clock::now();
  if (out.empty() && !ending) {
    if (peer_left(c.socket)) return false;
    if (now - c.sent < std::chrono::seconds(15)) return true;
    out = ": keep-alive\n\n";
  }
  if (!out.empty() && !sink.write(out.data(), out.size())) return false;  // the browser left
  c.sent = now;
  if (ending) sink.done();  // the run's last events are out
  return true;
}

DashboardServer::DashboardServer(const DashboardOptions& opt) : impl_(std::make_unique<Impl>(opt)) {
  Impl& d = *impl_;
  if (!fs::is_directory(opt.run_dir)) throw std::runtime_error(opt.run_dir + ": not a run directory");
  // Called once listening, when d.port is known.
  d.http.new_task_queue = [&d] {
    GateLimits g;
    g.deadline = d.opt.request_deadline;
    return new RequestGate(static_cast<std::size_t>(d.opt.threads), d.port, g);
  };
  d.http.set_socket_options([&d](int fd) {
    httplib::default_socket_options(fd);
    d.listener = fd;
  });
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
    const std::string client = req.remote_addr;
    if (const std::string full = d.slots.take(client); !full.empty()) {
      res.set_header("Retry-After", "5");
      return json_error(res, 503, full + ": try again later");
    }
    auto cursor = std::make_shared<StreamCursor>(StreamCursor{since, connection_from(d.port, client, req.remote_port)});
    d.watcher.poll();
    ++d.streams;
    res.set_chunked_content_provider("text/event-stream", [&d, cursor](size_t, httplib::DataSink& sink) {
      return d.send_events(*cursor, sink);
    }, [&d, client](bool) {
      d.slots.give_back(client);
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
    const std::string why = cadence_problem(r, st["dt"].get<double>(), st["end_time"].get<double>());
    if (!why.empty()) return json_error(res, 400, why);
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
  d.http.set_payload_max_length(4096);  // a control request is a few dozen bytes
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
  // cpp-httplib listens with a backlog of 5 (built in): a burst of page loads overflowed it.
  if (d.listener >= 0) ::listen(d.listener, opt.listen_backlog);
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
