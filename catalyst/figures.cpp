#include "catalyst/figures.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>

#include <nlohmann/json.hpp>

#include "catalyst/headless_display.hpp"
#include "catalyst/pipeline_scripts.hpp"
#include "catalyst/run_program.hpp"

namespace fs = std::filesystem;

namespace psph {

int render_figures(const std::string& run_dir, const std::vector<std::string>& requested, std::ostream& log) {
  const fs::path run = fs::absolute(run_dir).lexically_normal();
  const fs::path settings_path = run / "images" / "visualisation.json";
  if (!fs::is_regular_file(settings_path)) {
    log << "poresph: figures " << run_dir << ": no images/visualisation.json: this is not a run directory of a run "
        << "with pipelines (run it with --pipeline NAME first)\n";
    return 2;
  }
  nlohmann::json settings;
  try {
    std::ifstream(settings_path) >> settings;
  } catch (const std::exception& e) {
    log << "poresph: figures " << settings_path.string() << ": not valid JSON: " << e.what() << "\n";
    return 2;
  }
  std::vector<std::string> scripts;
  try {
    for (const auto& p : requested.empty() ? settings.at("pipelines").get<std::vector<std::string>>() : requested)
      scripts.push_back(find_pipeline(p).path);
  } catch (const std::exception& e) {
    log << "poresph: figures: " << e.what() << "\n";
    return 2;
  }
  // The particle extracts in order, with their times from particles.pvd.
  std::ifstream pvd(run / "extracts" / "particles.pvd");
  const std::regex entry("timestep=\"([^\"]+)\" file=\"([^\"]+)\"");
  std::string line, list;
  int frames = 0;
  while (std::getline(pvd, line)) {
    std::smatch m;
    if (!std::regex_search(line, m, entry)) continue;
    list += m[1].str() + "\t" + (run / "extracts" / m[2].str()).string() + "\n";
    ++frames;
  }
  if (frames == 0) {
    log << "poresph: figures " << run_dir << ": no particle extracts listed in extracts/particles.pvd\n";
    return 2;
  }
  // The run directory may have moved since the run: point the settings at it.
  settings["images_dir"] = (run / "images").string();
  settings["extracts_dir"] = (run / "extracts").string();
  settings["live_url"] = "";
  const fs::path work = run / "images" / ".figures";
  fs::create_directories(work);
  std::ofstream(work / "visualisation.json") << settings.dump(2);
  std::ofstream(work / "extracts.txt") << list;

  std::unique_ptr<HeadlessDisplay> display;
  try {
    std::string note;
    display = HeadlessDisplay::ensure(note);
    log << "figures: " << note << "\n";
  } catch (const std::exception& e) {
    log << "poresph: figures: " << e.what() << "\n";
    return 4;
  }
  setenv("PORESPH_VIS_SETTINGS", (work / "visualisation.json").c_str(), 1);
  std::vector<std::string> cmd{PORESPH_PVBATCH, (fs::path(pipeline_directory()) / "render_extracts.py").string(),
                               (work / "extracts.txt").string()};
  cmd.insert(cmd.end(), scripts.begin(), scripts.end());
  log << "figures: re-rendering " << frames << " frames of " << scripts.size() << " pipeline(s) with pvbatch\n";
  if (const int rc = run_program(cmd); rc != 0) {
    log << "poresph: figures: pvbatch failed (exit " << rc << ")\n";
    return 4;
  }
  fs::remove_all(work);

  // One MP4 per pipeline and view, when ffmpeg is installed.
  for (const std::string& s : scripts) {
    const fs::path dir = run / "images" / fs::path(s).stem();
    for (const char* view : {"3d", "slab"}) {
      if (!fs::exists(dir / (std::string(view) + "_000000.png"))) continue;
      const std::string mp4 = (dir / (std::string(view) + ".mp4")).string();
      const int rc = run_program({"ffmpeg", "-y", "-loglevel", "error", "-framerate", "10", "-i",
                                  (dir / (std::string(view) + "_%06d.png")).string(), "-c:v", "libx264", "-pix_fmt",
                                  "yuv420p", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", mp4});
      if (rc == 127) {
        log << "figures: ffmpeg not found, no MP4 assembled (apt-get install ffmpeg)\n";
        return 0;
      }
      log << "figures: " << (rc == 0 ? "wrote " + mp4 : "ffmpeg failed for " + mp4) << "\n";
    }
  }
  return 0;
}

}  // namespace psph
