// tensile_pull: pulls M specimens of a yarn in the virtual constant-rate-of-extension tester and
// prints each specimen's force-elongation trace and break as CSV (scripts/tensile_test turns it
// into a lab report and a plot). Core only: no ROS. `tensile_pull --help` lists the options.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "yarn_tearing/core/lab/tensile_pull.hpp"

namespace {

constexpr const char* kUsage = R"(usage: tensile_pull --curve S0,P0;S1,P1;... --density RHO
                    (--radius R | --tex T [--packing-fraction PHI]) [options]
  --curve             stress-strain points "strain,stress [Pa];..." from (0,0); 2nd = yield,
                      last = break (sigma_b, the mean strength at the gauge length)
  --density           fibre density [kg/m^3]
  --rate-sensitivity  k [per decade of strain rate] (default 0: rate-independent)
  --radius | --tex    yarn radius [m] | linear density [g/km]; --packing-fraction with --tex
  --gauge-length      length at which sigma_b and the scatter hold [m] (default 0.5)
  --length            clamped specimen length [m] (default: the gauge length)
  --strength-cv | --weibull-modulus   strength scatter at the gauge length (default none)
  --specimens         number of specimens M (default 20); seeds SEED, SEED+1, ...
  --seed              first seed (default 1)
  --vertices          vertices per specimen (default 21)
  --time-step         [s] (default 0.001)
  --extension-rate    clamp speed over specimen length [1/s] (default 1/60: 100 %/min)
output (CSV, one row per line; '#' lines are comments):
  trace,SPECIMEN,ELONGATION [-],FORCE [N]       load cell along the pull
  break,SPECIMEN,ELONGATION [-],FORCE [N],EDGE  the tear (or: unbroken,SPECIMEN)
exit status: 0 ok, 2 invalid arguments
)";

double number(const std::string& key, const std::string& text) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(value)) {
    throw std::invalid_argument("--" + key + " expects a finite number, got '" + text + "'");
  }
  return value;
}

std::vector<yarn_tearing::CurvePoint> curvePoints(const std::string& text) {
  std::vector<yarn_tearing::CurvePoint> points;
  std::stringstream pairs(text);
  std::string pair;
  while (std::getline(pairs, pair, ';')) {
    const std::size_t comma = pair.find(',');
    if (comma == std::string::npos) {
      throw std::invalid_argument("--curve expects 'strain,stress;...', got '" + pair + "'");
    }
    points.push_back(
        {number("curve", pair.substr(0, comma)), number("curve", pair.substr(comma + 1))});
  }
  return points;
}

std::map<std::string, std::string> parseOptions(int argc, char** argv) {
  static const char* const kKeys[] = {"curve",           "density",   "rate-sensitivity",
                                      "radius",          "tex",       "packing-fraction",
                                      "gauge-length",    "length",    "strength-cv",
                                      "weibull-modulus", "specimens", "seed",
                                      "vertices",        "time-step", "extension-rate"};
  std::map<std::string, std::string> options;
  for (int i = 1; i < argc; i += 2) {
    const std::string flag = argv[i];
    bool known = false;
    for (const char* key : kKeys) known = known || flag == std::string("--") + key;
    if (!known) throw std::invalid_argument("unknown option '" + flag + "'");
    if (i + 1 >= argc) throw std::invalid_argument(flag + " needs a value");
    options[flag.substr(2)] = argv[i + 1];
  }
  if (options.count("radius") != 0 && options.count("tex") != 0) {
    throw std::invalid_argument("either --radius or --tex, not both");
  }
  for (const char* required : {"curve", "density"}) {
    if (options.count(required) == 0) {
      throw std::invalid_argument(std::string("--") + required + " is required");
    }
  }
  return options;
}

/// The specimen and the number of specimens from the options; throws std::invalid_argument.
yarn_tearing::YarnSpec specimen(const std::map<std::string, std::string>& options) {
  auto value = [&](const char* key, double fallback) {
    const auto it = options.find(key);
    return it == options.end() ? fallback : number(key, it->second);
  };
  yarn_tearing::YarnSpec spec;
  spec.name = "specimen";
  spec.material.name = "tensile_pull";
  spec.material.density = value("density", 0.0);
  spec.material.rate_sensitivity = value("rate-sensitivity", 0.0);
  spec.material.curve = yarn_tearing::StressStrainCurve(curvePoints(options.at("curve")));
  spec.tex = value("tex", 0.0);
  spec.radius = spec.tex > 0.0 ? 0.0 : value("radius", 1.0e-4);
  spec.packing_fraction = value("packing-fraction", spec.packing_fraction);
  spec.strength_scatter.gauge_length = value("gauge-length", 0.5);
  spec.length = value("length", spec.strength_scatter.gauge_length);
  spec.strength_scatter.coefficient_of_variation = value("strength-cv", 0.0);
  spec.strength_scatter.weibull_modulus = value("weibull-modulus", 0.0);
  const double vertices = value("vertices", 21.0);
  if (!(vertices >= 2.0 && vertices <= 1.0e5 && vertices == std::floor(vertices))) {
    throw std::invalid_argument("--vertices must be an integer in [2, 100000]");
  }
  spec.num_vertices = static_cast<int>(vertices);
  spec.direction = Eigen::Vector3d::UnitX();
  spec.validate();
  return spec;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
    std::cout << kUsage;
    return 0;
  }
  yarn_tearing::YarnSpec spec;
  yarn_tearing::TensilePullSettings settings;
  int specimens = 0;
  unsigned long long first_seed = 1;
  try {
    const std::map<std::string, std::string> options = parseOptions(argc, argv);
    spec = specimen(options);
    auto integer = [&](const char* key, double fallback, double low, double high) {
      const auto it = options.find(key);
      const double x = it == options.end() ? fallback : number(key, it->second);
      if (!(x >= low && x <= high && x == std::floor(x))) {
        throw std::invalid_argument(std::string("--") + key + " must be an integer in [" +
                                    std::to_string(static_cast<long long>(low)) + ", " +
                                    std::to_string(static_cast<long long>(high)) + "]");
      }
      return x;
    };
    specimens = static_cast<int>(integer("specimens", 20.0, 1.0, 1.0e6));
    first_seed = static_cast<unsigned long long>(integer("seed", 1.0, 0.0, 1.0e15));
    if (options.count("time-step") != 0) {
      settings.time_step = number("time-step", options.at("time-step"));
    }
    if (options.count("extension-rate") != 0) {
      settings.extension_rate = number("extension-rate", options.at("extension-rate"));
    }
    if (!(settings.time_step > 0.0 && settings.time_step <= 0.1)) {
      throw std::invalid_argument("--time-step must be in (0, 0.1] [s]");
    }
    if (!(settings.extension_rate > 0.0)) {
      throw std::invalid_argument("--extension-rate must be > 0 [1/s]");
    }
  } catch (const std::invalid_argument& e) {
    std::cerr << "tensile_pull: error: " << e.what() << "\n" << kUsage;
    return 2;
  }

  std::printf("# tensile_pull: %d specimens of %.6g m, gauge length %.6g m, %.6g %%/min\n",
              specimens, spec.length, spec.strength_scatter.gauge_length,
              100.0 * 60.0 * settings.extension_rate);
  std::printf("# kind,specimen,elongation [-],force [N],edge\n");
  for (int i = 0; i < specimens; ++i) {
    spec.strength_scatter.seed = first_seed + static_cast<unsigned long long>(i);
    const yarn_tearing::TensilePullResult pull = yarn_tearing::pullSpecimen(spec, settings);
    for (const yarn_tearing::TensileSample& s : pull.trace) {
      std::printf("trace,%d,%.9g,%.9g\n", i, s.elongation, s.force);
    }
    if (pull.torn) {
      std::printf("break,%d,%.9g,%.9g,%u\n", i, pull.elongation_at_break, pull.breaking_force,
                  pull.torn_edge);
    } else {
      std::printf("unbroken,%d\n", i);
    }
  }
  return 0;
}
