#include "yarn_tearing/ros/yarn_spec_loader.hpp"

#include <limits>
#include <stdexcept>
#include <string>

#include "yarn_tearing/ros/material_loader.hpp"
#include "yarn_tearing/ros/parameter_bounds.hpp"
#include "yarn_tearing/ros/parameter_error.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

namespace bounds = parameter_bounds;

void loadSize(const ParamValue& yarn, YarnSpec& spec) {
  if (yarn.has("radius") && yarn.has("tex")) {
    yarn.member("tex").fail("either radius [m] or tex [g/km] in one yarn, not both");
  }
  if (yarn.has("tex")) {
    spec.tex = yarn.member("tex").number(bounds::kMinTex, bounds::kMaxTex, "g/km");
    spec.radius = 0.0;
    if (yarn.has("packing_fraction")) {
      spec.packing_fraction = yarn.member("packing_fraction").number(1.0e-3, 1.0, "");
    }
  } else {
    if (yarn.has("packing_fraction")) {
      yarn.member("packing_fraction").fail("packing_fraction only together with tex");
    }
    spec.radius = yarn.member("radius").number(bounds::kMinRadius, bounds::kMaxRadius, "m");
  }
}

/// length, num_vertices, start and direction: the whole yarn within kMaxPosition of the origin,
/// segments of at least kMinSegment.
void loadGeometry(const ParamValue& yarn, YarnSpec& spec) {
  const ParamValue length = yarn.member("length");
  spec.length = length.number(bounds::kMinSegment, bounds::kMaxLength, "m");
  const ParamValue num_vertices = yarn.member("num_vertices");
  spec.num_vertices = num_vertices.integer(2, bounds::kMaxYarnVertices);
  if (spec.length / (spec.num_vertices - 1) < bounds::kMinSegment) {
    num_vertices.fail("at most length / 1e-6 m + 1 vertices (segments of at least 1 um)");
  }
  spec.start = yarn.member("start").boundedVector3(bounds::kMaxPosition, "m");
  const ParamValue direction = yarn.member("direction");
  spec.direction = direction.vector3("");
  const double norm = spec.direction.norm();
  if (!(norm >= bounds::kMinDirection && norm <= bounds::kMaxDirection)) {
    direction.fail("a vector [x, y, z] of magnitude in [1e-6, 1e6]");
  }
  const Eigen::Vector3d end = spec.start + spec.length / norm * spec.direction;
  if (!(end.norm() <= bounds::kMaxPosition)) {
    length.fail(
        "a length that keeps the yarn's end start + length * direction within 1e4 m of "
        "the origin");
  }
}

std::vector<int> loadPinned(const ParamValue& pinned, int num_vertices) {
  std::vector<int> list = pinned.integerList();
  for (int index : list) {
    if (index < -num_vertices || index >= num_vertices) {
      pinned.fail("vertex indices in [" + std::to_string(-num_vertices) + ", " +
                  std::to_string(num_vertices - 1) + "] (negative counts from the end)");
    }
  }
  return list;
}

}  // namespace

void loadYarnMaking(const ParamValue& yarn, const ParamValue& presets, YarnSpec& spec) {
  spec.material = loadMaterial(yarn.member("material"), presets);
  loadSize(yarn, spec);
  if (yarn.has("weibull_modulus")) {
    const ParamValue modulus = yarn.member("weibull_modulus");
    const double m = modulus.number(0.0, bounds::kMaxWeibullModulus, "");
    if (m > 0.0 && m < 1.0) {
      modulus.fail("0 (no scatter) or a number in [1, 1000] (a coefficient of variation <= 1)");
    }
    spec.strength_scatter.weibull_modulus = m;
  }
  if (yarn.has("strength_cv")) {
    const ParamValue cv = yarn.member("strength_cv");
    if (yarn.has("weibull_modulus")) {
      cv.fail("either strength_cv or weibull_modulus, not both (remove one)");
    }
    spec.strength_scatter.coefficient_of_variation = cv.number(0.0, 1.0, "");
  }
  if (yarn.has("gauge_length")) {
    spec.strength_scatter.gauge_length =
        yarn.member("gauge_length").number(bounds::kMinSegment, bounds::kMaxLength, "m");
  }
  if (yarn.has("seed")) {
    spec.strength_scatter.seed = static_cast<unsigned long long>(
        yarn.member("seed").integer(0, std::numeric_limits<int>::max()));
  }
}

YarnSpec loadYarnSpec(const ParamValue& yarn, const ParamValue& presets) {
  if (!yarn.isStruct()) {
    yarn.fail("a map {name, material, radius, length, num_vertices, start, direction, pinned}");
  }
  yarn.requireKeysIn({"name", "material", "radius", "tex", "packing_fraction", "length",
                      "num_vertices", "start", "direction", "pinned", "end_mass", "weibull_modulus",
                      "strength_cv", "gauge_length", "seed"});
  YarnSpec spec;
  spec.name = yarn.member("name").string(false);
  loadYarnMaking(yarn, presets, spec);
  loadGeometry(yarn, spec);
  if (yarn.has("pinned")) {
    spec.pinned = loadPinned(yarn.member("pinned"), spec.num_vertices);
  }
  if (yarn.has("end_mass")) {
    spec.end_mass = yarn.member("end_mass").number(0.0, bounds::kMaxEndMass, "kg");
  }
  try {
    spec.validate();
  } catch (const std::invalid_argument& e) {
    yarn.fail(std::string("a valid yarn (") + e.what() + ")");
  }
  return spec;
}

}  // namespace ros_layer
}  // namespace yarn_tearing
