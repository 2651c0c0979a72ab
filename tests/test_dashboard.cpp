// The dashboard's server over real HTTP (cpp-httplib's client), on a run directory the tests
// write as a run would: the token guards control, nothing outside the run's images, extracts and
// records is served, malformed requests get 4xx, a reader that leaves harms nobody, many readers
// are served at once; and the run's side: control requests in order, status.json.
#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>
#include <httplib.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include "app/output_clock.hpp"
#include "dashboard_fixture.hpp"


TEST(Dashboard, ControlNeedsTheRunsToken) {
  Served s("token");
  const std::string wrong(s.run.token.size(), '0'), shorter = s.run.token.substr(1);
  EXPECT_EQ(post_control(s, R"({"action":"pause"})", nullptr), 403);
  EXPECT_EQ(post_control(s, R"({"action":"pause"})", &wrong), 403);
  EXPECT_EQ(post_control(s, R"({"action":"pause"})", &shorter), 403);
  EXPECT_FALSE(fs::exists(s.run.dir / "control"));  // nothing reached the run
  EXPECT_EQ(post_control(s, R"({"action":"pause"})", &s.run.token), 202);
  EXPECT_EQ(post_control(s, R"({"action":"cadence","monitor_interval":0.01})", &s.run.token), 202);
  // Malformed: 400, nothing posted.
  EXPECT_EQ(post_control(s, "{not json", &s.run.token), 400);
  EXPECT_EQ(post_control(s, R"({"action":"explode"})", &s.run.token), 400);
  EXPECT_EQ(post_control(s, R"({"action":"cadence","monitor_interval":-1})", &s.run.token), 400);
  EXPECT_EQ(post_control(s, R"({"action":"cadence"})", &s.run.token), 400);
  EXPECT_EQ(post_control(s, R"([1,2])", &s.run.token), 400);
  EXPECT_EQ(post_control(s, R"({"action":"cadence","monitor_interval":1e-300})", &s.run.token), 400);  // under the floor
  // The run takes exactly the two good ones, in order.
  ControlInbox inbox(s.run.dir.string(), 0);
  const auto got = inbox.take();
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0].action, ControlRequest::Action::Pause);
  EXPECT_EQ(got[1].action, ControlRequest::Action::Cadence);
  EXPECT_DOUBLE_EQ(got[1].monitor_interval, 0.01);
  EXPECT_TRUE(inbox.take().empty());  // taken once
}

TEST(Dashboard, AFinishedRunTakesNoControl) {
  Served s("finished", "completed");
  EXPECT_EQ(post_control(s, R"({"action":"stop"})", &s.run.token), 409);
  fs::remove(s.run.dir / "token");  // a run directory without a token: no control at all
  EXPECT_EQ(post_control(s, R"({"action":"stop"})", &s.run.token), 403);
}

TEST(Dashboard, ServesOnlyTheRunsImagesExtractsAndRecords) {
  Served s("paths");
  EXPECT_EQ(status_of(s, "/run/images/phases/3d_000000.png"), 200);
  EXPECT_EQ(status_of(s, "/run/extracts/particles_000000.vtp"), 200);
  EXPECT_EQ(status_of(s, "/run/monitors.csv"), 200);
  EXPECT_EQ(status_of(s, "/run/case.resolved.toml"), 200);
  EXPECT_EQ(status_of(s, "/run/images/phases/none.png"), 404);
  {  // a file larger than one streamed piece arrives whole
    std::string big(300 * 1024 + 7, '\0');
    for (std::size_t k = 0; k < big.size(); ++k) big[k] = static_cast<char>(k * 31 % 251);
    std::ofstream(s.run.dir / "extracts" / "big.vtp", std::ios::binary) << big;
    auto r = s.client().Get("/run/extracts/big.vtp");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200);
    EXPECT_TRUE(r->body == big);
  }
  // The token, control requests, checkpoints, and anything outside: refused.
  for (const char* p : {"/run/token", "/run/control/x.json", "/run/checkpoints/step_0000000010.ckpt", "/run/images/../token",
                        "/run/images/%2e%2e/token", "/run/images/..%2ftoken", "/run/../../../etc/passwd",
                        "/run/%2e%2e/%2e%2e/etc/passwd", "/run//etc/passwd", "/run/images/./phases/3d_000000.png",
                        "/run/images", "/run/images\\..\\token"})
    EXPECT_EQ(status_of(s, p), 403) << p;
  // A link inside images/ that leads out of the run directory.
  fs::create_symlink(s.run.dir / "token", s.run.dir / "images" / "phases" / "leak.png");
  EXPECT_EQ(status_of(s, "/run/images/phases/leak.png"), 403);
  // Nor the token under another name: a hard link to it placed in images/.
  fs::create_hard_link(s.run.dir / "token", s.run.dir / "images" / "phases" / "3d_000001.png");
  auto linked = s.client().Get("/run/images/phases/3d_000001.png");
  ASSERT_TRUE(linked);
  EXPECT_EQ(linked->status, 403);
  EXPECT_EQ(linked->body.find(s.run.token), std::string::npos);
  // The static front-end directory does not exist here: / says so rather than failing.
  EXPECT_EQ(status_of(s, "/../../etc/passwd"), 404);
}

TEST(Dashboard, OnLoopbackOnlyRequestsNamingItAreAnswered) {
  Served s("host");
  httplib::Client c = s.client();
  for (const char* host : {"evil.example", "evil.example:80", "127.0.0.1:1", "127.0.0.1"}) {
    auto r = c.Get("/api/state", httplib::Headers{{"Host", host}});
    ASSERT_TRUE(r) << host;
    EXPECT_EQ(r->status, 403) << host;
  }
  auto r = c.Get("/api/state", httplib::Headers{{"Host", "localhost:" + std::to_string(s.server.port())}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
}

TEST(Dashboard, MalformedRequestsGetFourHundredsAndTheServerCarriesOn) {
  Served s("malformed");
  for (const std::string raw : {std::string("GARBAGE\r\n\r\n"), std::string("GET\r\n\r\n"),
                                std::string("GET /api/state HTTP/9.9\r\nHost: x\r\n\r\n"),
                                std::string("POST /api/control HTTP/1.1\r\nContent-Length: 99999999\r\n\r\n"),
                                std::string(10000, 'A') + "\r\n\r\n"}) {
    const int fd = connect_from(s.server.port());
    ASSERT_GE(fd, 0);
    ASSERT_GT(::send(fd, raw.data(), raw.size(), MSG_NOSIGNAL), 0);
    ::shutdown(fd, SHUT_WR);
    char buf[256] = {};
    const auto n = ::recv(fd, buf, sizeof buf - 1, 0);
    ::close(fd);
    if (n > 0) EXPECT_TRUE(std::string(buf).rfind("HTTP/1.1 4", 0) == 0) << raw.substr(0, 40) << " -> " << buf;
  }
  EXPECT_EQ(status_of(s, "/api/state"), 200);
  EXPECT_EQ(status_of(s, "/api/events?since=abc"), 400);
}

TEST(Dashboard, StateHoldsEverythingSoFar) {
  Served s("state");
  auto r = s.client().Get("/api/state");
  ASSERT_TRUE(r);
  const auto j = nlohmann::json::parse(r->body);
  EXPECT_EQ(j["status"]["state"], "running");
  EXPECT_EQ(j["columns"].size(), 3u);
  EXPECT_EQ(j["rows"].size(), 2u);
  ASSERT_EQ(j["frames"].size(), 1u);
  EXPECT_EQ(j["frames"][0]["images"][0]["url"], "run/images/phases/3d_000000.png");  // relative: behind a prefix too
  ASSERT_EQ(j["extracts"].size(), 1u);
  EXPECT_EQ(j["extracts"][0]["url"], "run/extracts/particles_000000.vtp");
  EXPECT_TRUE(j["control"].get<bool>());
}

// Reads an event stream until `want` appears in it (or `timeout`).
std::string read_events(int port, const std::string& path, const std::string& want, std::chrono::milliseconds timeout,
                        std::atomic<bool>* stop_early = nullptr) {
  httplib::Client c("127.0.0.1", port);
  c.set_read_timeout(std::chrono::duration_cast<std::chrono::seconds>(timeout).count() + 1, 0);
  std::string got;
  const auto end = std::chrono::steady_clock::now() + timeout;
  c.Get(path.c_str(), [&](const char* data, size_t n) {
    got.append(data, n);
    return got.find(want) == std::string::npos && std::chrono::steady_clock::now() < end && !(stop_early && *stop_early);
  });
  return got;
}

TEST(Dashboard, ManyReadersGetTheNewRowsAndOneThatLeavesHarmsNone) {
  Served s("readers");
  // A reader that leaves at once (a closed tab).
  read_events(s.server.port(), "/api/events?since=0", "event: status", std::chrono::milliseconds(3000));
  constexpr int kReaders = 7;  // with the one that left, as many as one address may have
  std::vector<std::string> seen(kReaders);
  std::vector<std::thread> readers;
  for (int k = 0; k < kReaders; ++k)
    readers.emplace_back([&, k] {
      seen[k] = read_events(s.server.port(), "/api/events?since=0", "[20.0,0.002,", std::chrono::milliseconds(15000));
    });
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  s.run.append_row("20,0.002,3e-7\n");
  for (auto& t : readers) t.join();
  for (int k = 0; k < kReaders; ++k) {
    EXPECT_NE(seen[k].find("event: columns"), std::string::npos) << k;
    EXPECT_NE(seen[k].find("event: frame"), std::string::npos) << k;
    EXPECT_NE(seen[k].find("event: monitors\ndata: [[20.0,0.002,"), std::string::npos) << k << ": " << seen[k].substr(0, 300);
  }
  EXPECT_EQ(status_of(s, "/api/state"), 200);
}

TEST(Dashboard, EventsResumeAfterTheLastOneSeen) {
  Served s("resume");
  const std::string all = read_events(s.server.port(), "/api/events?since=0", "event: status", std::chrono::milliseconds(3000));
  EXPECT_NE(all.find("id: 1\n"), std::string::npos);
  s.run.set_state("paused");
  const std::string later = read_events(s.server.port(), "/api/events?since=5", "paused", std::chrono::milliseconds(3000));
  EXPECT_EQ(later.find("id: 1\n"), std::string::npos);  // nothing before event 6
  EXPECT_NE(later.find("\"state\":\"paused\""), std::string::npos) << later;
}

TEST(RunWatcher, TakesOnlyCompleteLinesAndFramesOnceRecorded) {
  FakeRun run("watcher");
  RunWatcher w(run.dir.string());
  w.poll();
  EXPECT_EQ(w.snapshot()["rows"].size(), 2u);
  run.append_row("20,0.0");  // half a row: not yet
  w.poll();
  EXPECT_EQ(w.snapshot()["rows"].size(), 2u);
  run.append_row("02,3e-7\n");
  w.poll();
  ASSERT_EQ(w.snapshot()["rows"].size(), 3u);
  EXPECT_DOUBLE_EQ(w.snapshot()["rows"][2][1].get<double>(), 0.002);
  // An image on disk without its frames.csv row is not a frame yet (it may be half-written).
  std::ofstream(run.dir / "images" / "phases" / "3d_000001.png") << "png";
  w.poll();
  EXPECT_EQ(w.snapshot()["frames"].size(), 1u);
  std::ofstream(run.dir / "images" / "frames.csv", std::ios::app) << "1,20,0.002\n";
  w.poll();
  EXPECT_EQ(w.snapshot()["frames"].size(), 2u);
}

TEST(RunWatcher, ARunWhoseProcessIsGoneIsLost) {
  FakeRun run("lost");
  RunStatus s;
  s.case_name = "fake", s.state = "running";
  StatusFile(run.dir.string()).write(s);
  auto j = nlohmann::json::parse(std::ifstream(run.dir / "status.json"));
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  ::waitpid(child, nullptr, 0);
  j["pid"] = child;  // a process that has ended
  std::ofstream(run.dir / "status.json") << j.dump();
  RunWatcher w(run.dir.string());
  w.poll();
  EXPECT_EQ(w.snapshot()["status"]["state"], "lost");
}

TEST(RunWatcher, AKilledRunIsLostInItsStatusFileToo) {
  FakeRun run("killed");
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  if (child == 0) {  // a run that writes its status, then is killed before its last word
    run.set_state("running");
    [[maybe_unused]] auto n = ::write(ready[1], "x", 1);
    for (;;) ::pause();
  }
  ASSERT_GT(child, 0);
  char c;
  ASSERT_EQ(::read(ready[0], &c, 1), 1);
  ::kill(child, SIGKILL);
  ::waitpid(child, nullptr, 0);
  ::close(ready[0]), ::close(ready[1]);
  auto on_disk = [&] { return nlohmann::json::parse(std::ifstream(run.dir / "status.json"))["state"].get<std::string>(); };
  EXPECT_EQ(on_disk(), "running");  // what it left
  RunWatcher w(run.dir.string());
  w.poll();
  EXPECT_EQ(w.snapshot()["status"]["state"], "lost");
  EXPECT_EQ(on_disk(), "lost");  // for every later reader too
  EXPECT_NE(w.snapshot()["status"]["diagnostic"].get<std::string>().find(std::to_string(child)), std::string::npos);
}

TEST(RunWatcher, ARunWhosePidIsNowAnothersIsLost) {
  FakeRun run("reused");  // written by this process: alive, and its start time recorded
  RunWatcher w(run.dir.string());
  w.poll();
  EXPECT_EQ(w.snapshot()["status"]["state"], "running");
  auto j = nlohmann::json::parse(std::ifstream(run.dir / "status.json"));
  EXPECT_GT(j["pid_start"].get<long>(), 0);
  j["pid_start"] = j["pid_start"].get<long>() - 1;  // the same pid, another process
  std::ofstream(run.dir / "status.json") << j.dump();
  w.poll();
  EXPECT_EQ(w.snapshot()["status"]["state"], "lost");
}

TEST(RunWatcher, AnOlderRunDirectoryShowsItsSummary) {
  FakeRun run("summary");
  fs::remove(run.dir / "status.json");
  RunWatcher w(run.dir.string());
  w.poll();
  EXPECT_TRUE(w.snapshot()["status"].is_null());  // neither file: no status yet
  std::ofstream(run.dir / "summary.json") << R"({"case": "old", "status": "completed", "backend": "cpu", "device": "x",
    "precision": "double", "dimension": 2, "particles": 208, "steps": 1600, "time": 0.5, "end_time": 0.5,
    "wall_seconds": 1.5, "particle_steps_per_second": 2e5})";
  w.poll();
  const auto st = w.snapshot()["status"];
  EXPECT_EQ(st["state"], "completed");
  EXPECT_EQ(st["case"], "old");
  EXPECT_EQ(st["step"], 1600);
}

TEST(RunControl, RequestsParseOrRefuseWithTheReason) {
  EXPECT_EQ(control_request_from_json(nlohmann::json::parse(R"({"action":"resume"})")).action, ControlRequest::Action::Resume);
  auto says = [](const char* text) {
    try {
      control_request_from_json(nlohmann::json::parse(text));
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(says(R"({"action":"jump"})").find("\"jump\""), std::string::npos);
  EXPECT_NE(says(R"({"verb":"stop"})").find("action"), std::string::npos);
  EXPECT_NE(says(R"({"action":"cadence","extract_interval":"soon"})").find("extract_interval"), std::string::npos);
  // A request file the run cannot read is removed and reported, the others still taken.
  FakeRun run("inbox");
  post_control_request(run.dir.string(), ControlRequest{ControlRequest::Action::Stop});
  std::ofstream(run.dir / "control" / "req_zzz.json") << "{broken";
  std::vector<std::string> rejected;
  const auto got = ControlInbox(run.dir.string(), 0).take(&rejected);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].action, ControlRequest::Action::Stop);
  ASSERT_EQ(rejected.size(), 1u);
  EXPECT_NE(rejected[0].find("req_zzz.json"), std::string::npos);
  EXPECT_TRUE(fs::is_empty(run.dir / "control"));
  // An output interval longer than the run (1e308 s once overflowed the output clocks).
  ControlRequest c{ControlRequest::Action::Cadence};
  c.monitor_interval = 1e308;
  EXPECT_NE(cadence_problem(c, 1e-4, 1).find("monitor_interval: 1e+308 s is longer than the run"), std::string::npos);
  c.monitor_interval = 1e-9;
  EXPECT_NE(cadence_problem(c, 1e-4, 1).find("shorter"), std::string::npos);
  c.monitor_interval = 0.5;
  EXPECT_EQ(cadence_problem(c, 1e-4, 1), "");
  // The token is the owner's alone.
  EXPECT_EQ(fs::status(run.dir / "token").permissions() & (fs::perms::group_all | fs::perms::others_all), fs::perms::none);
}

TEST(OutputClock, MultiplesOfTheIntervalAfterTheStartAndAfterAChange) {
  OutputClock c(0.01, 0.0);
  EXPECT_DOUBLE_EQ(c.next(), 0.01);
  EXPECT_FALSE(c.due(0.0099));
  EXPECT_TRUE(c.due(0.01 * (1 - 1e-13)));  // a step that lands a rounding short of it
  c.pass(0.0305);                          // a long step past two of them: the next one after it
  EXPECT_DOUBLE_EQ(c.next(), 0.04);
  OutputClock restart(0.01, 0.025);  // a restart part-way
  EXPECT_DOUBLE_EQ(restart.next(), 0.03);
  c.set_interval(0.004, 0.0305);  // the dashboard's cadence: the next multiple of the new interval
  EXPECT_DOUBLE_EQ(c.next(), 0.032);
}
