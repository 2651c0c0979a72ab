// The fuzz target of the case reader: any bytes as a case file go through what `poresph check`
// does (parse, check, build the particles, make the engine, check the output fields) and a step.
// A refusal (CaseError), an engine that refuses the scene, or a run that goes unstable is a fine
// outcome; anything else that escapes, a crash, a sanitizer report or a hang is a finding. Built
// with libFuzzer (tests/fuzz/CMakeLists.txt, label `fuzz`) and, with a small main, as the replay
// of the corpus and of every input that ever failed (`fuzz_replay`, in make test).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/instability.hpp"
#include "engine/engine.hpp"
#include "scene/case_file.hpp"
#include "scene/scene_builder.hpp"

namespace {

// One input must take well under a second: cases that would build more are accepted unbuilt.
constexpr double kMostPoints = 2e5;
constexpr int kMostEngineParticles = 3000;

void engine_and_a_step(psph::Case& c) {
  if (c.scene.count() > kMostEngineParticles) return;
  try {
    auto e = psph::make_engine(c.scene, "cpu");
    psph::check_output_fields(c, e->field_names());
    e->step(c.end_time);
  } catch (const psph::CaseError&) {
  } catch (const psph::InstabilityError&) {
  } catch (const std::invalid_argument&) {  // the engine refuses the scene, with a message
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    psph::Case c = psph::load_case_text(text, "fuzz.toml");
    if (psph::particle_work_estimate(c) > kMostPoints) return 0;
    psph::build_particles(c);
    engine_and_a_step(c);
  } catch (const psph::CaseError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: an exception that is not a case error: %s\n", e.what());
    std::abort();
  }
  return 0;
}
