#include "yarn_tearing/ros/material_loader.hpp"

#include <stdexcept>
#include <vector>

#include "yarn_tearing/core/material/rate_dependence.hpp"
#include "yarn_tearing/ros/parameter_bounds.hpp"
#include "yarn_tearing/ros/parameter_error.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

namespace bounds = parameter_bounds;

/// Fails unless Young's modulus is within bounds and every segment after the yield point is
/// less steep than it (the curve bends over after yield, config/materials.yaml).
void requireBendsOverAfterYield(const ParamValue& curve_param, const StressStrainCurve& curve) {
  const double modulus = curve.youngsModulus();
  if (!(modulus >= bounds::kMinYoungsModulus && modulus <= bounds::kMaxYoungsModulus)) {
    curve_param.fail("a first segment (Young's modulus) of slope in [1e3, 1e13] Pa");
  }
  const std::vector<CurvePoint>& p = curve.points();
  for (std::size_t i = 2; i < p.size(); ++i) {
    const double slope = (p[i].stress - p[i - 1].stress) / (p[i].strain - p[i - 1].strain);
    if (!(slope < modulus)) {
      curve_param.fail("every segment after the yield point less steep than the first (E = " +
                       std::to_string(modulus) + " Pa); segment " + std::to_string(i) +
                       " has slope " + std::to_string(slope) + " Pa");
    }
  }
}

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
    point.strain = xy[0].number(0.0, bounds::kMaxCurveStrain, "");
    point.stress = xy[1].number(0.0, bounds::kMaxCurveStress, "Pa");
    points.push_back(point);
  }
  try {
    const StressStrainCurve loaded(std::move(points));
    requireBendsOverAfterYield(curve, loaded);
    return loaded;
  } catch (const std::invalid_argument& e) {
    curve.fail(allowed + " (" + e.what() + ")");
  }
}

/// Reads a material map; `strict` rejects unknown keys (inline materials; presets may carry
/// documentation keys of their own).
Material loadMaterialMap(const ParamValue& map, const std::string& name, bool strict) {
  if (strict) {
    map.requireKeysIn(
        {"density", "rate_sensitivity", "plastic_viscosity", "stress_strain", "source"});
  }
  Material material;
  material.name = name;
  material.density =
      map.member("density").number(bounds::kMinDensity, bounds::kMaxDensity, "kg/m^3");
  // plastic_viscosity (eta) was replaced by rate_sensitivity; files that say 0.0 (rate
  // independent) still load.
  if (map.has("plastic_viscosity") &&
      map.member("plastic_viscosity").nonNegativeNumber("Pa*s") != 0.0) {
    map.member("plastic_viscosity")
        .fail(
            "0.0: plastic_viscosity was replaced by rate_sensitivity [per decade of strain rate]"
            " (config/MATERIALS.md)");
  }
  material.rate_sensitivity =
      map.has("rate_sensitivity")
          ? map.member("rate_sensitivity").number(0.0, RateDependence::kMaxSensitivity, "")
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
                    ") or an inline map {density, rate_sensitivity, stress_strain}");
    }
    return loadMaterialMap(presets.member(preset), preset, false);
  }
  if (!material.isStruct()) {
    material.fail(
        "a preset name or an inline map {density: kg/m^3, rate_sensitivity: per decade, "
        "stress_strain: [[strain, Pa], ...]}");
  }
  return loadMaterialMap(material, "inline", true);
}

}  // namespace ros_layer
}  // namespace yarn_tearing
