#include "yarn_tearing/ros/fabric_spec_loader.hpp"

#include <array>
#include <stdexcept>
#include <string>

#include "yarn_tearing/ros/parameter_bounds.hpp"
#include "yarn_tearing/ros/yarn_spec_loader.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

namespace bounds = parameter_bounds;

FabricFamily loadFamily(const ParamValue& value) {
  return value.choice<FabricFamily>({{"warp", FabricFamily::kWarp}, {"weft", FabricFamily::kWeft}});
}

YarnSpec loadFamilyYarn(const ParamValue& fabric, const char* key, const ParamValue& presets) {
  const ParamValue yarn = fabric.member(key);
  if (!yarn.isStruct()) yarn.fail("a map {material, radius | tex, weibull_modulus, ...}");
  yarn.requireKeysIn({"material", "radius", "tex", "packing_fraction", "weibull_modulus",
                      "strength_cv", "gauge_length", "seed"});
  YarnSpec spec;
  loadYarnMaking(yarn, presets, spec);
  return spec;
}

Eigen::Vector3d loadDirection(const ParamValue& fabric, const char* key,
                              const Eigen::Vector3d& fallback) {
  if (!fabric.has(key)) return fallback;
  const ParamValue direction = fabric.member(key);
  const Eigen::Vector3d d = direction.vector3("");
  if (!(d.norm() >= bounds::kMinDirection && d.norm() <= bounds::kMaxDirection)) {
    direction.fail("a vector [x, y, z] of magnitude in [1e-6, 1e6]");
  }
  return d;
}

void loadGrid(const ParamValue& fabric, FabricSpec& spec) {
  spec.warp_length =
      fabric.member("warp_length").number(bounds::kMinSegment, bounds::kMaxLength, "m");
  spec.weft_length =
      fabric.member("weft_length").number(bounds::kMinSegment, bounds::kMaxLength, "m");
  spec.ends = fabric.member("ends").integer(2, bounds::kMaxYarnVertices);
  spec.picks = fabric.member("picks").integer(2, bounds::kMaxYarnVertices);
  if (spec.warp_length / (spec.picks - 1) < bounds::kMinSegment) {
    fabric.member("picks").fail("at most warp_length / 1e-6 m + 1 picks (segments of >= 1 um)");
  }
  if (spec.weft_length / (spec.ends - 1) < bounds::kMinSegment) {
    fabric.member("ends").fail("at most weft_length / 1e-6 m + 1 ends (segments of >= 1 um)");
  }
  if (fabric.has("origin")) {
    spec.origin = fabric.member("origin").boundedVector3(bounds::kMaxPosition, "m");
  }
  spec.warp_direction = loadDirection(fabric, "warp_direction", spec.warp_direction);
  spec.weft_direction = loadDirection(fabric, "weft_direction", spec.weft_direction);
  // Every corner within the bound (the origin is one; a flat parallelogram's others follow).
  const Eigen::Vector3d warp = spec.warp_length * spec.warp_direction.normalized();  // [m]
  const Eigen::Vector3d weft = spec.weft_length * spec.weft_direction.normalized();  // [m]
  const std::array<Eigen::Vector3d, 3> corners = {spec.origin + warp, spec.origin + weft,
                                                  spec.origin + warp + weft};
  for (const Eigen::Vector3d& corner : corners) {
    if (!(corner.norm() <= bounds::kMaxPosition)) {
      fabric.member("warp_length")
          .fail("sizes that keep every corner of the fabric within 1e4 m of the origin");
    }
  }
}

void loadPins(const ParamValue& fabric, FabricSpec& spec) {
  if (fabric.has("pinned")) {
    for (const ParamValue& entry : fabric.member("pinned").elements()) {
      const std::vector<int> pair = entry.integerList();
      if (pair.size() != 2 || pair[0] < -spec.picks || pair[0] >= spec.picks ||
          pair[1] < -spec.ends || pair[1] >= spec.ends) {
        entry.fail("[row, column] with row in [" + std::to_string(-spec.picks) + ", " +
                   std::to_string(spec.picks - 1) + "] and column in [" +
                   std::to_string(-spec.ends) + ", " + std::to_string(spec.ends - 1) +
                   "] (negative counts from the end)");
      }
      spec.pinned.push_back({pair[0], pair[1]});
    }
  }
  if (fabric.has("pinned_sides")) {
    for (const ParamValue& side : fabric.member("pinned_sides").elements()) {
      spec.pinned_sides.push_back(
          side.choice<FabricSide>({{"first_row", FabricSide::kFirstRow},
                                   {"last_row", FabricSide::kLastRow},
                                   {"first_column", FabricSide::kFirstColumn},
                                   {"last_column", FabricSide::kLastColumn}}));
    }
  }
}

void loadSlits(const ParamValue& fabric, FabricSpec& spec) {
  if (!fabric.has("slits")) return;
  for (const ParamValue& entry : fabric.member("slits").elements()) {
    if (!entry.isStruct()) entry.fail("a map {family, first_yarn, last_yarn, segment}");
    entry.requireKeysIn({"family", "first_yarn", "last_yarn", "segment"});
    FabricSlit slit;
    slit.family = loadFamily(entry.member("family"));
    const int yarns = spec.yarnCount(slit.family);
    slit.first_yarn = entry.member("first_yarn").integer(0, yarns - 1);
    slit.last_yarn = entry.member("last_yarn").integer(slit.first_yarn, yarns - 1);
    slit.segment = entry.member("segment").integer(0, spec.segmentsPerYarn(slit.family) - 1);
    spec.slits.push_back(slit);
  }
}

}  // namespace

FabricSpec loadFabricSpec(const ParamValue& fabric, const ParamValue& presets) {
  if (!fabric.isStruct()) {
    fabric.fail("a map {name, warp_length, weft_length, ends, picks, warp, weft, ...}");
  }
  fabric.requireKeysIn({"name", "weave", "warp_length", "weft_length", "ends", "picks", "origin",
                        "warp_direction", "weft_direction", "warp", "weft", "warp_crimp",
                        "weft_crimp", "shear_rigidity", "pinned", "pinned_sides", "slits"});
  FabricSpec spec;
  spec.name = fabric.member("name").string(false);
  if (fabric.has("weave"))
    spec.weave = fabric.member("weave").choice<Weave>({{"plain", Weave::kPlain}});
  loadGrid(fabric, spec);
  spec.warp = loadFamilyYarn(fabric, "warp", presets);
  spec.weft = loadFamilyYarn(fabric, "weft", presets);
  if (fabric.has("warp_crimp")) spec.warp_crimp = fabric.member("warp_crimp").number(0.0, 1.0, "");
  if (fabric.has("weft_crimp")) spec.weft_crimp = fabric.member("weft_crimp").number(0.0, 1.0, "");
  if (fabric.has("shear_rigidity")) {
    spec.shear_rigidity =
        fabric.member("shear_rigidity").number(0.0, bounds::kMaxShearRigidity, "N/m");
  }
  loadPins(fabric, spec);
  loadSlits(fabric, spec);
  try {
    spec.validate();
  } catch (const std::invalid_argument& e) {
    fabric.fail(std::string("a valid fabric (") + e.what() + ")");
  }
  return spec;
}

}  // namespace ros_layer
}  // namespace yarn_tearing
