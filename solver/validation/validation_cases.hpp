#pragma once
// The validation suite behind `poresph validate`: each case compares the solver with an analytical
// solution or a published number and returns records {case, metric, value, reference, error,
// tolerance, passed} (GUIDE §5). Reduced sizes by default, the published sizes with --full.
#include <functional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace psph {

struct ValidationRecord {
  std::string case_name, metric;
  double value = 0, reference = 0;
  double error = 0;      // relative error as a fraction, or an absolute difference where stated
  double tolerance = 0;
  bool passed = false;
};

// A case that cannot run here (its data are missing): reported skipped, never passed.
struct ValidationUnavailable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ValidationContext {
  bool full = false;
  std::string backend = "cpu";
  std::ostream* log = nullptr;  // progress lines, may be null
};

struct ValidationCase {
  std::string name, description;
  std::function<std::vector<ValidationRecord>(const ValidationContext&)> run;
  // The largest |rho/rho0 - 1| its runs may reach (GUIDE §3): 3 %, 1 % for a permeability.
  double density_bound = 0.03;
};

const std::vector<ValidationCase>& validation_cases();

// Records for a metric where `error` is |value - reference| / |reference_scale|.
ValidationRecord make_record(const std::string& case_name, const std::string& metric, double value,
                             double reference, double error, double tolerance);

}  // namespace psph
