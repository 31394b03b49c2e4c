#include "yarn_tearing/ros/material_loader.hpp"

#include <limits>
#include <stdexcept>
#include <vector>

#include "yarn_tearing/ros/parameter_error.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

constexpr double kUnbounded = std::numeric_limits<double>::max();

StressStrainCurve loadCurve(const ParamValue& curve) {
  const std::string allowed =
      "a list of at least 3 [strain, stress] pairs ([-], [Pa]) starting at [0, 0], strictly "
      "increasing in both (point 1 = yield, last = break)";
  if (curve.raw().getType() != XmlRpc::XmlRpcValue::TypeArray) {
    curve.fail(allowed);
  }
  std::vector<CurvePoint> points;
  for (const ParamValue& pair : curve.elements()) {
    const std::vector<ParamValue> xy = pair.elements();
    if (xy.size() != 2) {
      curve.fail(allowed);
    }
    CurvePoint point;
    point.strain = xy[0].number(-kUnbounded, kUnbounded, "");
    point.stress = xy[1].number(-kUnbounded, kUnbounded, "Pa");
    points.push_back(point);
  }
  try {
    return StressStrainCurve(std::move(points));
  } catch (const std::invalid_argument& e) {
    curve.fail(allowed + " (" + e.what() + ")");
  }
}

/// Reads a material map; `strict` rejects unknown keys (inline materials; presets may carry
/// documentation keys of their own).
Material loadMaterialMap(const ParamValue& map, const std::string& name, bool strict) {
  if (strict) {
    map.requireKeysIn({"density", "plastic_viscosity", "stress_strain", "source"});
  }
  Material material;
  material.name = name;
  material.density = map.member("density").positiveNumber("kg/m^3");
  material.plastic_viscosity = map.has("plastic_viscosity")
                                   ? map.member("plastic_viscosity").nonNegativeNumber("Pa*s")
                                   : 0.0;
  material.curve = loadCurve(map.member("stress_strain"));
  try {
    material.validate();
  } catch (const std::invalid_argument& e) {
    map.fail(std::string("a valid material (") + e.what() + ")");
  }
  return material;
}

std::string presetNames(const ParamValue& presets) {
  if (!presets.isStruct()) {
    return "none loaded";
  }
  std::string names;
  for (const std::string& key : presets.keys()) {
    names += (names.empty() ? "" : ", ") + key;
  }
  return names.empty() ? "none loaded" : names;
}

}  // namespace

Material loadMaterial(const ParamValue& material, const ParamValue& presets) {
  if (material.isString()) {
    const std::string preset = material.string(false);
    if (!presets.has(preset)) {
      material.fail("the name of a preset in " + presets.name() + " (" + presetNames(presets) +
                    ") or an inline map {density, plastic_viscosity, stress_strain}");
    }
    return loadMaterialMap(presets.member(preset), preset, false);
  }
  if (!material.isStruct()) {
    material.fail(
        "a preset name or an inline map {density: kg/m^3, plastic_viscosity: Pa*s, "
        "stress_strain: [[strain, Pa], ...]}");
  }
  return loadMaterialMap(material, "inline", true);
}

}  // namespace ros_layer
}  // namespace yarn_tearing
