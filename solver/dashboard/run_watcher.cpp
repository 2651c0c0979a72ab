#include "dashboard/run_watcher.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "dashboard/run_status.hpp"

namespace psph {
namespace fs = std::filesystem;
namespace {

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The bytes of `p` after `offset`, up to its last newline; advances `offset` past them.
std::string new_lines(const fs::path& p, std::uintmax_t& offset) {
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(p, ec);
  if (ec || size <= offset) return "";
  std::ifstream in(p, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(offset));
  std::string chunk(size - offset, '\0');
  in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
  chunk.resize(static_cast<std::size_t>(in.gcount()));
  const auto last = chunk.rfind('\n');
  if (last == std::string::npos) return "";
  chunk.resize(last + 1);
  offset += chunk.size();
  return chunk;
}

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream s(line);
  while (std::getline(s, item, sep)) out.push_back(item);
  return out;
}

}  // namespace

RunWatcher::RunWatcher(std::string run_dir) : dir_(std::move(run_dir)) {}

void RunWatcher::emit(const std::string& type, nlohmann::json data) {
  DashboardEvent e;
  e.id = ++seq_;
  e.type = type;
  e.data = std::move(data);
  if (type == "status") status_event_ = std::move(e);  // only the latest is kept: the log stays
  else events_.push_back(std::move(e));                // as long as the run's own records
}

void RunWatcher::poll() {
  {
    std::lock_guard<std::mutex> lock(m_);
    const long before = seq_;
    // Each source on its own: a file that cannot be read now (permissions, a bad link, a half
    // write) is tried again at the next poll and never takes the server down.
    for (void (RunWatcher::*source)() : {&RunWatcher::poll_monitors, &RunWatcher::poll_frames, &RunWatcher::poll_extracts,
                                         &RunWatcher::poll_status}) {  // status last: a final state after what it ends
      try {
        (this->*source)();
      } catch (const std::exception&) {
      }
    }
    if (seq_ == before) return;
  }
  cv_.notify_all();
}

// A run directory from before status.json: its final state from summary.json (throws without one).
nlohmann::json RunWatcher::status_of_summary() const {
  const nlohmann::json m = nlohmann::json::parse(read_file(fs::path(dir_) / "summary.json"));
  RunStatus s;
  s.state = m.at("status"), s.case_name = m.at("case"), s.backend = m.at("backend"), s.device = m.at("device");
  s.precision = m.at("precision"), s.dimension = m.at("dimension"), s.particles = m.at("particles");
  s.step = m.at("steps"), s.time = m.at("time"), s.end_time = m.at("end_time"), s.elapsed = m.at("wall_seconds");
  s.time_left = 0;
  return to_json(s);
}

void RunWatcher::poll_status() {
  const std::string text = read_file(fs::path(dir_) / "status.json");
  nlohmann::json j;
  try {
    j = text.empty() ? status_of_summary() : nlohmann::json::parse(text);
    status_from_json(j);  // complete and well-typed (throws otherwise)
  } catch (const std::exception&) {
    return;  // none yet
  }
  mark_lost(dir_, j);  // a live state whose process has gone (killed before it could say so)
  const std::string now = j.dump();
  if (now == status_text_) return;
  status_text_ = now;
  status_ = j;
  emit("status", j);
}

void RunWatcher::poll_monitors() {
  const std::string chunk = new_lines(fs::path(dir_) / "monitors.csv", monitor_offset_);
  if (chunk.empty()) return;
  nlohmann::json rows = nlohmann::json::array();
  std::istringstream s(chunk);
  std::string line;
  while (std::getline(s, line)) {
    if (line.empty()) continue;
    if (columns_.empty()) {
      for (const auto& c : split(line, ',')) columns_.push_back(c);
      emit("columns", columns_);
      continue;
    }
    nlohmann::json row = nlohmann::json::array();
    for (const auto& v : split(line, ',')) {
      try {
        row.push_back(std::stod(v));
      } catch (const std::exception&) {
        row.push_back(nullptr);  // nan, inf or text: no point on the chart
      }
    }
    rows.push_back(row);
    rows_.push_back(row);
  }
  if (!rows.empty()) emit("monitors", rows);
}

void RunWatcher::poll_frames() {
  const fs::path images = fs::path(dir_) / "images";
  const std::string chunk = new_lines(images / "frames.csv", frames_offset_);
  if (chunk.empty()) return;
  std::istringstream s(chunk);
  std::string line;
  while (std::getline(s, line)) {
    const std::vector<std::string> f = split(line, ',');
    if (f.size() != 3 || f[0] == "frame") continue;
    nlohmann::json frame;
    try {
      frame = {{"frame", std::stol(f[0])}, {"step", std::stol(f[1])}, {"time", std::stod(f[2])}};
    } catch (const std::exception&) {
      continue;
    }
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, "_%06ld.png", frame["frame"].get<long>());
    nlohmann::json list = nlohmann::json::array();
    std::error_code ec;
    std::vector<fs::path> found;
    for (const auto& pipe : fs::directory_iterator(images, ec)) {
      if (!pipe.is_directory()) continue;
      for (const auto& img : fs::directory_iterator(pipe.path(), ec)) {
        const std::string name = img.path().filename().string();
        if (name.size() > std::strlen(suffix) && name.compare(name.size() - std::strlen(suffix), std::string::npos, suffix) == 0)
          found.push_back(img.path());
      }
    }
    std::sort(found.begin(), found.end());
    for (const fs::path& p : found) {
      const std::string name = p.filename().string();
      list.push_back({{"pipeline", p.parent_path().filename().string()},
                      {"view", name.substr(0, name.size() - std::strlen(suffix))},
                      {"url", "run/images/" + p.parent_path().filename().string() + "/" + name}});
    }
    frame["images"] = list;
    frames_.push_back(frame);
    emit("frame", frame);
  }
}

void RunWatcher::poll_extracts() {
  const std::string text = read_file(fs::path(dir_) / "extracts" / "particles.pvd");
  if (text == pvd_text_) return;
  pvd_text_ = text;
  static const std::regex entry(R"re(<DataSet\s+timestep="([^"]*)"\s+file="([^"/\\]*\.p?vt[pu])"\s*/>)re");
  std::size_t index = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), entry); it != std::sregex_iterator(); ++it, ++index) {
    if (index < extracts_.size()) continue;
    nlohmann::json e;
    try {
      e = {{"index", index}, {"time", std::stod((*it)[1].str())}, {"url", "run/extracts/" + (*it)[2].str()}};
    } catch (const std::exception&) {
      break;
    }
    extracts_.push_back(e);
    emit("extract", e);
  }
}

nlohmann::json RunWatcher::snapshot() const {
  std::lock_guard<std::mutex> lock(m_);
  return {{"status", status_}, {"columns", columns_}, {"rows", rows_}, {"frames", frames_},
          {"extracts", extracts_}, {"last_event", seq_}};
}

std::vector<DashboardEvent> RunWatcher::events_after(long since, std::chrono::milliseconds wait) const {
  std::unique_lock<std::mutex> lock(m_);
  if (since < 0) since = 0;
  cv_.wait_for(lock, wait, [&] { return stopped_ || seq_ > since; });
  std::vector<DashboardEvent> out;
  auto first = std::lower_bound(events_.begin(), events_.end(), since + 1,
                                [](const DashboardEvent& e, long id) { return e.id < id; });
  out.assign(first, events_.end());
  if (status_event_.id > since)  // in its place among the others
    out.insert(std::lower_bound(out.begin(), out.end(), status_event_.id,
                                [](const DashboardEvent& e, long id) { return e.id < id; }),
               status_event_);
  return out;
}

void RunWatcher::stop() {
  {
    std::lock_guard<std::mutex> lock(m_);
    stopped_ = true;
  }
  cv_.notify_all();
}

bool RunWatcher::stopped() const {
  std::lock_guard<std::mutex> lock(m_);
  return stopped_;
}

}  // namespace psph
