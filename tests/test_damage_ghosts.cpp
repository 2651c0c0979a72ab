// Damage ghosts (damage/ghosts.hpp; Pazdniakou 2018 §4.7, Fig. 14d): a notched strip pulled
// apart by its grips (tests/ghost_strip.hpp), with Rankine-Mohr-Coulomb damage and degraded = "ghost", breaks at the
// notch: the particles whose damage reached the threshold drop out, stay at rest where they
// dropped out, carry no strain, and the two halves part, unloaded, where the deviatoric law keeps
// carrying the load through its intact bulk modulus. In small strain and in Saint Venant-Kirchhoff
// (whose lists of t = 0 lose the ghosts); a restart from a checkpoint that holds a ghost not yet
// out of the lists continues bitwise. And in the pressurised pore (cases/pressurised_pore_2d.toml),
// the water flows into the crack of ghosts that it opens.
#include <algorithm>
#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "case_text.hpp"
#include "ghost_strip.hpp"
#include "core/damage_ghost.hpp"
#include "engine/engine.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"

using namespace psph;

// The strip breaks by 1.1 ms (6 ghosts, the ligament below the notch).
constexpr double kBroken = 1.5e-3, kLater = 3e-3;

namespace {

std::unique_ptr<Engine> engine_of(const std::string& text) {
  Case c = load_case_text(text, "strip.toml");
  build_particles(c);
  return make_engine(c.scene, "cpu");
}

std::string strip(const char* model, const char* degraded) {
  return test::replaced(test::replaced(test::ghost_strip_case(), "[solid]\n", std::string("[solid]\nmodel = \"") + model + "\"\n"),
                        "degraded = \"ghost\"", std::string("degraded = \"") + degraded + "\"");
}

double monitor(Engine& e, const std::string& name) {
  for (const auto& m : e.monitors())
    if (m.name == name) return m.value;
  ADD_FAILURE() << "no monitor " << name;
  return 0;
}

// Field `name` (components per particle `comps`) by particle id.
std::map<int, std::vector<double>> by_id(Engine& e, const std::string& name, int comps) {
  const auto f = e.field(name), id = e.field("id");
  std::map<int, std::vector<double>> out;
  for (std::size_t i = 0; i < id.size(); ++i) out[int(id[i])].assign(f.begin() + comps * i, f.begin() + comps * (i + 1));
  return out;
}

const char* kModels[] = {"linear", "saint_venant_kirchhoff"};

}  // namespace

TEST(DamageGhosts, TheStripBreaksAtTheNotchAndItsGhostsDropOut) {
  for (const char* model : kModels) {
    SCOPED_TRACE(model);
    auto e = engine_of(strip(model, "ghost"));
    e->run_until(kBroken);
    const auto ghost = by_id(*e, "damage_ghost", 1), x = by_id(*e, "position", 2);
    const auto v = by_id(*e, "velocity", 2), eps = by_id(*e, "strain", 4), d = by_id(*e, "damage", 1);
    const auto x0 = by_id(*e, "reference_position", 2);
    int ghosts = 0;
    for (const auto& [id, g] : ghost) {
      if (g[0] == 0) continue;
      ++ghosts;
      EXPECT_LT(std::fabs(x0.at(id)[0]), 0.004) << "a ghost away from the notch, id " << id;
      EXPECT_GE(d.at(id)[0], 0.99) << id;
      if (g[0] != kGhostRetired) continue;
      EXPECT_EQ(v.at(id)[0], 0.0) << id;
      EXPECT_EQ(v.at(id)[1], 0.0) << id;
      for (double c : eps.at(id)) EXPECT_EQ(c, 0.0) << id;
    }
    EXPECT_GT(ghosts, 0);
    EXPECT_EQ(monitor(*e, "ghost_particles"), ghosts);
    const double broken_energy = monitor(*e, "elastic_energy");
    e->run_until(kLater);
    const auto x_later = by_id(*e, "position", 2), ghost_later = by_id(*e, "damage_ghost", 1);
    for (const auto& [id, g] : ghost)
      if (g[0] == kGhostRetired) {
        EXPECT_EQ(ghost_later.at(id)[0], kGhostRetired) << id;
        EXPECT_EQ(x_later.at(id), x.at(id)) << "ghost " << id << " moved";
      }
    // Parted: the halves unload while the grips go on; the deviatoric law keeps the load.
    auto kept = engine_of(strip(model, "deviatoric"));
    kept->run_until(kLater);
    EXPECT_LT(monitor(*e, "elastic_energy"), 0.2 * monitor(*kept, "elastic_energy"));  // measured 0.075
    EXPECT_LT(monitor(*e, "elastic_energy"), broken_energy);
  }
}

TEST(DamageGhosts, ARestartAcrossAPendingGhostIsBitwise) {
  for (const char* model : kModels) {
    SCOPED_TRACE(model);
    auto e = engine_of(strip(model, "ghost"));
    auto pending = [&] {
      const auto g = e->field("damage_ghost");
      return std::count(g.begin(), g.end(), double(kGhostPending)) > 0;
    };
    while (!pending() && e->time() < kLater) e->step(kLater);
    ASSERT_TRUE(pending());
    const Checkpoint ck = e->checkpoint();
    const auto before = by_id(*e, "damage_ghost", 1);
    e->step(kLater);  // the next step's list build retires the pending ghosts
    for (const auto& [id, g] : by_id(*e, "damage_ghost", 1)) {
      if (before.at(id)[0] == kGhostPending) EXPECT_EQ(g[0], kGhostRetired) << id;
    }
    e->run_until(kBroken);  // and from one that holds retired ghosts (restored lists of t = 0 pruned)
    const Checkpoint broken = e->checkpoint();
    e->run_until(kBroken + 2e-4);
    for (const Checkpoint* c : {&ck, &broken}) {  // with the same stops as the run they continue
      auto r = engine_of(strip(model, "ghost"));
      r->restore(*c);
      if (c == &ck) r->step(kLater), r->run_until(kBroken);
      r->run_until(kBroken + 2e-4);
      EXPECT_EQ(by_id(*r, "position", 2), by_id(*e, "position", 2));
      EXPECT_EQ(by_id(*r, "damage_ghost", 1), by_id(*e, "damage_ghost", 1));
      EXPECT_EQ(by_id(*r, "damage", 1), by_id(*e, "damage", 1));
    }
  }
}

// The pressurised pore without confinement, its water at 0.5 MPa from the start and rising at
// 1 MPa/ms (a fast load: the crack runs to the block's faces by 1 ms), ghosts at D_t = 1
// (combination "max"): a crack one particle wide along the pore's axis from both tips, into which
// the water flows past the pore's tip (12.25 mm; measured at 1.5 ms: 13.3 mm; with "deviatoric"
// the damaged particles keep their place and the water stays at 12.1 mm).
TEST(DamageGhosts, TheWaterFlowsIntoTheCrackOfGhosts) {
  std::string text = embedded_case_text("pressurised_pore_2d");
  text = text.substr(0, text.find("# The confining stress"));
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"materials = [\"clay\"]", "materials = [\"clay\"]\ndegraded = \"ghost\"\ncombination = \"max\""},
           {"background_pressure = 1.0e5", "background_pressure = 5.0e5"},
           {"background_pressure_rate = 5.0e8", "background_pressure_rate = 1.0e9"},
           {"end = 0.006", "end = 0.0015"}})
    text = test::replaced(text, from, to);
  auto e = engine_of(text);
  const auto x0 = e->field("position"), mat0 = e->field("material");
  std::size_t centre = 0;
  for (std::size_t i = 0; i < mat0.size(); ++i)
    if (std::hypot(x0[2 * i], x0[2 * i + 1]) < std::hypot(x0[2 * centre], x0[2 * centre + 1])) centre = i;
  const double water = mat0[centre];
  e->run_until(1.5e-3);
  const auto x = e->field("position"), mat = e->field("material"), ghost = e->field("damage_ghost");
  const auto ref = e->field("reference_position");
  double reach = 0;
  int left = 0, right = 0;
  for (std::size_t i = 0; i < mat.size(); ++i) {
    if (mat[i] == water) reach = std::max(reach, std::fabs(x[2 * i]));
    if (ghost[i] == 0) continue;
    EXPECT_LT(std::fabs(ref[2 * i + 1]), 0.5e-3) << "a ghost off the pore's axis at y = " << ref[2 * i + 1];
    EXPECT_GT(std::fabs(ref[2 * i]), 0.01225) << "a ghost inside the pore's span";
    (ref[2 * i] < 0 ? left : right)++;
  }
  EXPECT_GT(left, 2);
  EXPECT_EQ(left, right);
  EXPECT_GT(reach, 0.01225 + 0.5e-3) << "the water did not enter the crack";
}
