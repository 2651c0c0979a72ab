// Case-file checking: each kind of bad input is rejected with the file, the key and what was
// expected.
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "case_text.hpp"
#include "scene/case_file.hpp"
#include "scene/case_reader.hpp"
#include "scene/embedded_cases.hpp"
#include "scene/scene_builder.hpp"

using namespace psph;

namespace {

std::string base_case() {
  for (const auto& c : embedded_cases())
    if (std::string(c.name) == "poiseuille_2d") return c.text;
  return "";
}

using test::error_of;
using test::replaced;

void expect_error(const std::string& text, std::initializer_list<const char*> parts) {
  const std::string msg = error_of(text);
  ASSERT_FALSE(msg.empty()) << "accepted a bad case";
  EXPECT_NE(msg.find("bad.toml"), std::string::npos) << msg;
  for (const char* p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
}

}  // namespace

TEST(CaseFile, EmbeddedCasesAreValid) {
  ASSERT_FALSE(embedded_cases().empty());
  for (const auto& c : embedded_cases()) EXPECT_EQ(error_of(c.text), "") << c.name;
}

TEST(CaseFile, UnknownKey) {
  expect_error(replaced(base_case(), "viscosity = 1.0e-3", "viscosity = 1.0e-3\nviscosty = 2.0"),
               {"materials.water.viscosty", "unknown key", "line"});
}

TEST(CaseFile, MissingRequiredValue) {
  expect_error(replaced(base_case(), "spacing = 5.0e-5", ""), {"discretisation.spacing", "missing required"});
  expect_error(replaced(base_case(), "[time]\nend = 0.5", ""), {"time", "missing required table"});
}

TEST(CaseFile, WrongType) {
  expect_error(replaced(base_case(), "density = 1000.0", "density = \"water\""),
               {"materials.water.density", "expected a number, got a string"});
  expect_error(replaced(base_case(), "dimension = 2", "dimension = 2.5"), {"case.dimension", "expected an integer"});
  expect_error(replaced(base_case(), "periodic = [false, true]", "periodic = [false]"),
               {"domain.periodic", "array of 2 booleans"});
}

TEST(CaseFile, NegativeSpacing) {
  expect_error(replaced(base_case(), "spacing = 5.0e-5", "spacing = -5.0e-5"),
               {"discretisation.spacing", "expected a number > 0", "-5e-05"});
}

TEST(CaseFile, ImpossibleTimeStep) {
  expect_error(replaced(base_case(), "[time]", "[solver]\ndt = 1.0\n\n[time]"), {"solver.dt"});
  expect_error(replaced(base_case(), "[time]", "[solver]\ndt = 1.0e-3\n\n[time]"),
               {"solver.dt", "impossible", "stability limit"});
  expect_error(replaced(base_case(), "end = 0.5", "end = -1.0"), {"time.end", "expected a number > 0"});
}

TEST(CaseFile, GeometryWithNoParticles) {
  expect_error(replaced(base_case(), "material = \"water\"", "material = \"empty\""),
               {"geometry", "no fluid, elastic or rigid particles"});
  expect_error(replaced(base_case(), "material = \"water\"", "material = \"oil\""),
               {"geometry[1].material", "\"oil\""});
}

TEST(CaseFile, BadChoiceListsTheOptions) {
  expect_error(replaced(base_case(), "kernel = \"cubic_spline\"", "kernel = \"gaussian\""),
               {"discretisation.kernel", "\"wendland_c2\"", "\"gaussian\""});
}

TEST(CaseFile, PeriodicAxisNeedsWholeSpacingsAndThreeSupports) {
  expect_error(replaced(base_case(), "upper = [1.15e-3, 4.0e-4]\nperiodic", "upper = [1.15e-3, 4.3e-4]\nperiodic"),
               {"discretisation.spacing", "whole number of spacings"});
  expect_error(replaced(base_case(), "support_radius = 1.0e-4", "support_radius = 1.5e-4"),
               {"support_radius", "shorter than 3 support radii"});
}

TEST(CaseFile, NotToml) {
  expect_error("[case\nname = 1", {"not valid TOML", "line 1"});
}

TEST(CaseFile, SmoothingLengthSetsSupportPerKernel) {
  std::string t = replaced(base_case(), "support_radius = 1.0e-4", "smoothing_length = 3.5e-5");
  t = replaced(t, "kernel = \"cubic_spline\"", "kernel = \"quintic_spline\"");
  Case c = load_case_text(t, "ok.toml");
  EXPECT_NEAR(c.scene.options.support_radius, 1.05e-4, 1e-12);
  expect_error(replaced(base_case(), "support_radius = 1.0e-4", "support_radius = 1.0e-4\nsmoothing_length = 5e-5"),
               {"exactly one of support_radius and smoothing_length"});
}

TEST(CaseFile, LatticeAndMasses) {
  Case c = load_case_text(base_case(), "ok.toml");
  build_particles(c);
  // 26 x 8 lattice sites, 20 x 8 of them water.
  EXPECT_EQ(c.scene.count(), 26 * 8);
  int water = 0;
  for (int m : c.scene.material) water += c.scene.materials[m].name == "water";
  EXPECT_EQ(water, 20 * 8);
}

// A key that would have no effect in the case is refused with the reason, not silently ignored.
TEST(CaseFile, KeysWithoutEffectAreRefused) {
  const std::string water = base_case();  // one fluid between walls, no surface tension
  auto with = [&](const std::string& table_and_key) { return replaced(water, "[time]", table_and_key + "\n\n[time]"); };
  expect_error(with("[solver]\ndensity_diffusion = 0.1"), {"solver.density_diffusion", "density = \"continuity\""});
  EXPECT_EQ(error_of(with("[solver]\ndensity = \"continuity\"\ndensity_diffusion = 0.1")), "");
  expect_error(with("[solver]\nimplicit_tolerance = 1e-8"), {"solver.implicit_tolerance", "implicit_viscosity = true"});
  EXPECT_EQ(error_of(with("[solver]\nimplicit_viscosity = true\nimplicit_tolerance = 1e-8")), "");
  expect_error(with("[interface]\nnormal_threshold = 0.02"), {"interface.normal_threshold", "surface_tension > 0"});
  expect_error(with("[interface]\nwetting = \"wall_colour\""), {"interface.wetting", "surface_tension > 0"});
  expect_error(with("[monitors]\nflow_axis = \"x\""), {"monitors.flow_axis", "a liquid and a gas"});
  expect_error(replaced(water, "[time]", "[time]\nafter_percolation = 0.1"), {"time.after_percolation", "a liquid and a gas"});
  expect_error(replaced(water, "sound_speed = 0.01", "sound_speed = 0.01\ntait_gamma = 7.0"),
               {"materials.water.tait_gamma", "equation_of_state = \"tait\""});
  // Without a fluid, the fluid's methods have nothing to act on.
  const std::string rod = embedded_case_text("vibrating_rod_1d");
  EXPECT_EQ(error_of(rod), "");
  expect_error(replaced(rod, "[time]", "[solver]\nxsph = 0.5\n\n[time]"),
               {"solver.xsph", "a material with kind = \"fluid\""});
  // With surface tension but no walls, the walls' wetting has nothing to act on.
  const std::string bubble = embedded_case_text("laplace_bubble_2d");
  EXPECT_EQ(error_of(bubble), "");
  expect_error(replaced(bubble, "[interface]", "[interface]\ncontact_line_force = false"),
               {"interface.contact_line_force", "kind = \"wall\""});
}

// Hostile files are refused before toml++ parses them (it recurses: 100,000 levels overflow the
// stack) or before they are read at all (a FIFO or a device would block or never end).
TEST(CaseFile, HostileFilesAreRefusedWithoutParsing) {
  std::string deep_header = "[";
  for (int k = 0; k < 100000; ++k) deep_header += "a.";
  expect_error(deep_header + "a]\n", {"nested", "expected at most 64"});
  expect_error("x = " + std::string(100000, '[') + std::string(100000, ']') + "\n", {"nested", "line 1"});
  expect_error(base_case() + "\n# " + std::string(2 << 20, 'x') + "\n", {"bytes; expected at most 1048576"});
  // Legal: an array of numbers over several lines (their dots are no nesting).
  EXPECT_EQ(error_of(replaced(base_case(), "lower = [-1.5e-4, 0.0]\nupper", "lower = [\n  -1.5e-4,\n  0.0]\nupper")), "");
  const std::string fifo = testing::TempDir() + "poresph_case_fifo";
  std::remove(fifo.c_str());
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& path : {fifo, std::string("/dev/zero"), testing::TempDir()}) {
    try {
      load_case_file(path);
      ADD_FAILURE() << path << " accepted";
    } catch (const CaseError& e) {
      EXPECT_NE(std::string(e.what()).find("expected a regular file"), std::string::npos) << e.what();
    }
  }
  std::remove(fifo.c_str());
}

// An echoed value is cut short and escaped: no 100 kB error line, no raw control or invalid bytes.
TEST(CaseFile, EchoedValuesAreShortAndEscaped) {
  const std::string huge = error_of(replaced(base_case(), "kind = \"fluid\"", "kind = \"" + std::string(100000, 'f') + "\""));
  EXPECT_LT(huge.size(), 1000u);
  EXPECT_NE(huge.find("..."), std::string::npos) << huge;
  const std::string odd = error_of(replaced(base_case(), "kind = \"fluid\"", "kind = \"fl\\u0001ui\\u202ed\""));
  EXPECT_NE(odd.find("fl\\x01ui\\xe2\\x80\\xaed"), std::string::npos) << odd;
  EXPECT_EQ(shown("caf\xc3\xa9"), "caf\xc3\xa9");  // UTF-8 kept
  EXPECT_EQ(shown("a\xff" "b"), "a\\xffb");          // not UTF-8: escaped
}

// Sizes that drive the cost are bounded before any work, in a type that cannot overflow.
TEST(CaseFile, UnboundedWorkIsRefusedBeforeItStarts) {
  expect_error(replaced(base_case(), "support_radius = 1.0e-4", "support_radius = 20.0"),
               {"discretisation.support_radius", "at most 10000 neighbour candidates", "(400000 spacings)"});
  // A 2 cm cube at 1e-9 m: 8e21 sites, past what a 64-bit product holds (it wrapped below the bound).
  const std::string tiny = replaced(replaced(embedded_case_text("elastic_cube_3d"), "spacing = 1.0e-3", "spacing = 1.0e-9"),
                                    "support_radius = 2.0e-3", "support_radius = 2.0e-9");
  const std::string tiny_short = replaced(tiny, "end = 0.01", "end = 1.0e-12");  // steps within bounds
  Case c = load_case_text(tiny_short, "tiny.toml");
  try {
    build_particles(c);
    ADD_FAILURE() << "built 1e18 sites";
  } catch (const CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("expected at most 4e8"), std::string::npos) << e.what();
  }
  const std::string ring = embedded_case_text("lame_cylinder_2d");
  EXPECT_EQ(error_of(ring), "");
  expect_error(replaced(ring, "radius = 0.02", "radius = 1.0e4"), {"geometry[", "].radius", "at most 4e8 particles"});
}

TEST(CaseFile, GrainPacksAreBoundedBeforeTheyAreDrawn) {
  const std::string pack = embedded_case_text("drainage_2d");
  EXPECT_EQ(error_of(pack), "");
  expect_error(replaced(pack, "grain_radius = ", "grain_radius = 1.0e-6 #"),
               {"].grain_radius", "at most 10000 grains, got about"});
}

TEST(CaseFile, CaseNamesThatBecomePathsAreChecked) {
  for (const char* bad : {"a\\u0000b", "a\\nb", "a\\u202eb", "a b", "../up", ".hidden", "-flag", "x/y", ""})
    expect_error(replaced(base_case(), "name = \"poiseuille_2d\"", std::string("name = \"") + bad + "\""),
                 {"case.name", "letters, digits"});
  expect_error(replaced(base_case(), "name = \"poiseuille_2d\"", "name = \"" + std::string(65, 'a') + "\""),
               {"case.name", "1 to 64"});
  EXPECT_EQ(error_of(replaced(base_case(), "name = \"poiseuille_2d\"", "name = \"" + std::string(64, 'a') + "\"")), "");
}

TEST(CaseFile, NumbersAreFiniteAndBounded) {
  for (const char* v : {"nan", "inf", "-inf", "1e308", "-1e308", "5e-324", "1e16"})
    expect_error(replaced(base_case(), "body_force = [0.0, 1.0e-3]", std::string("body_force = [0.0, ") + v + "]"),
                 {"materials.water.body_force", "expected a finite number, 0 or of magnitude in [1e-30, 1e15]"});
  expect_error(replaced(base_case(), "upper = [1.0e-3, 4.0e-4]", "upper = [inf, 4.0e-4]"), {"geometry[1].upper"});
  expect_error(replaced(base_case(), "end = 0.5", "end = 5e-324"), {"time.end", "finite number"});
  expect_error(replaced(base_case(), "density = 1000.0", "density = nan"), {"materials.water.density"});
}

TEST(CaseFile, ShapesOutsideTheDomainAreRefused) {
  expect_error(replaced(base_case(), "lower = [0.0, 0.0]\nupper = [1.0e-3, 4.0e-4]", "lower = [5.0, 0.0]\nupper = [6.0, 4.0e-4]"),
               {"geometry[1].upper", "overlaps the domain", "axis 0"});
  expect_error(replaced(base_case(), "lower = [0.0, 0.0]\nupper = [1.0e-3, 4.0e-4]", "lower = [1.0e-3, 0.0]\nupper = [0.0, 4.0e-4]"),
               {"geometry[1].upper", "upper > lower"});
}

// A lens: thinner than long, in 2D or 3D, about a named axis; it holds the sites of two discs'
// intersection (tips at +-half_length, faces at +-half_thickness).
TEST(CaseFile, ALensIsTheIntersectionOfTwoDiscs) {
  const std::string pore = embedded_case_text("pressurised_pore_2d");
  Case c = load_case_text(pore, "ok.toml");
  build_particles(c);
  int water = 0;
  double x_max = 0, y_max = 0;
  for (int i = 0; i < c.scene.count(); ++i) {
    if (c.scene.materials[c.scene.material[i]].name != "water") continue;
    ++water, x_max = std::max(x_max, std::fabs(c.scene.x[2 * i])), y_max = std::max(y_max, std::fabs(c.scene.x[2 * i + 1]));
  }
  EXPECT_NEAR(x_max, 0.012, 1e-9);  // the tip sites at +-12 mm (half_length 12.25 mm)
  EXPECT_NEAR(y_max, 0.003, 1e-9);  // the centre's at +-3 mm (half_thickness 3.25 mm)
  // Sites (x, y) with |y| <= b - (R - sqrt(R^2 - x^2)), R = (a^2 + b^2) / (2 b), on the 1 mm lattice.
  const double a = 12.25, b = 3.25, R = (a * a + b * b) / (2 * b);
  int expected = 0;
  for (int x = -12; x <= 12; ++x)
    for (int y = -3; y <= 3; ++y) expected += std::abs(y) <= b - (R - std::sqrt(R * R - x * x));
  EXPECT_EQ(water, expected);
  expect_error(replaced(pore, "half_thickness = 0.00325", "half_thickness = 0.02"),
               {"geometry[1].half_thickness", "less than half_length"});
  expect_error(replaced(pore, "axis = \"y\"", "axis = \"z\""), {"geometry[1].axis", "\"x\", \"y\""});
  expect_error(replaced(pore, "half_length = 0.01225\n", ""), {"geometry[1].half_length"});
  expect_error(replaced(pore, "axis = \"y\"", "axis = \"y\"\nlayout = \"concentric\""), {"geometry[1].layout", "lenses"});
}

// The background pressure's rate: not negative, not without a fluid nor with an open boundary.
TEST(CaseFile, BackgroundPressureRateNeedsAFluid) {
  const std::string rod = embedded_case_text("vibrating_rod_1d");
  expect_error(replaced(rod, "[time]", "[solver]\nbackground_pressure_rate = 1.0e6\n\n[time]"),
               {"solver.background_pressure_rate", "kind = \"fluid\""});
  const std::string pore = embedded_case_text("pressurised_pore_2d");
  Case c = load_case_text(pore, "ok.toml");
  EXPECT_EQ(c.scene.options.background_pressure_rate, 5e8);
  expect_error(replaced(pore, "background_pressure_rate = 5.0e8", "background_pressure_rate = -5.0e8"),
               {"solver.background_pressure_rate", ">= 0"});
  // The open boundary's buffers hold absolute pressures: refused beside a rising background.
  const std::string channel = embedded_case_text("open_channel_2d");
  expect_error(replaced(channel, "[time]", "[solver]\nbackground_pressure_rate = 1.0\n\n[time]"),
               {"solver.background_pressure_rate", "[open_boundary]"});
}

TEST(CaseFile, RunsThatCouldNotEndOrWouldFillTheDiskAreRefused) {
  const std::string c = base_case();
  expect_error(replaced(c, "kind = \"wall\"", "kind = \"wall\"\n[solver]\ndt_factor = 1e-7"),
               {"time.end", "at most 1e+09 steps, got about", "solver.dt_factor"});
  expect_error(replaced(c, "kind = \"wall\"", "kind = \"wall\"\n[solver]\ndt = 1e-29"), {"time.end", "solver.dt)"});
  expect_error(replaced(c, "material = \"water\"", "material = \"water\"\nvelocity = [1e12, 0.0]"), {"time.end", "steps"});
  expect_error(replaced(c, "extract_interval = 0.1", "extract_interval = 1e-9"),
               {"output.extract_interval", "at most 100000 extract files", "got 5e+08"});
  expect_error(replaced(c, "monitor_interval = 0.01", "monitor_interval = 1e-9"), {"output.monitor_interval", "monitor rows"});
  expect_error(replaced(c, "extract_interval = 0.1", "extract_interval = 0.1\ncheckpoint_interval = 1e-12"),
               {"output.checkpoint_interval", "checkpoints"});
  expect_error(c + "\n[visualisation]\ninterval = 1e-10\n", {"visualisation.interval", "frames per pipeline"});
}

TEST(CaseFile, OutputFieldsMustExistInTheCase) {
  Case c = load_case_text(replaced(base_case(), "extract_interval = 0.1", "extract_interval = 0.1\nfields = [\"velocity\", \"stress\"]"),
                          "f.toml");
  try {
    check_output_fields(c, {"position", "velocity", "pressure"});
    ADD_FAILURE() << "accepted a field the case does not have";
  } catch (const CaseError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("f.toml: output.fields: no particle field \"stress\" in this case; expected some of: position, "
                       "velocity, pressure"),
              std::string::npos)
        << msg;
  }
  EXPECT_NO_THROW(check_output_fields(c, {"velocity", "stress"}));
}
