#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "parameter_error_text.hpp"
#include "xmlrpc_builders.hpp"
#include "yarn_tearing/ros/fabric_spec_loader.hpp"
#include "yarn_tearing/ros/material_loader.hpp"
#include "yarn_tearing/ros/param_value.hpp"
#include "yarn_tearing/ros/parameter_error.hpp"
#include "yarn_tearing/ros/yarn_spec_loader.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

using testing::curve;
using testing::inlineMaterial;
using testing::list;
using testing::parameterErrorOf;
using testing::validYarn;

const ParamValue kNoPresets("/node/materials", XmlRpc::XmlRpcValue());

ParamValue yarnParam(const XmlRpc::XmlRpcValue& yarn) { return ParamValue("/node/yarns[0]", yarn); }

/// A copy of the map `map` without `key` (this XmlRpc has no deleteMember).
XmlRpc::XmlRpcValue withoutKey(XmlRpc::XmlRpcValue map, const std::string& key) {
  XmlRpc::XmlRpcValue copy;
  for (auto& member : map) {
    if (member.first != key) copy[member.first] = member.second;
  }
  return copy;
}

/// what() of the ParameterError that loading `yarn` throws ("" when none).
std::string yarnLoadError(const XmlRpc::XmlRpcValue& yarn, const ParamValue& presets = kNoPresets) {
  return parameterErrorOf([&] { loadYarnSpec(yarnParam(yarn), presets); });
}

TEST(YarnSpecLoader, LoadsAValidYarn) {
  XmlRpc::XmlRpcValue yarn = validYarn("weak");
  yarn["start"] = list({0.1, 0.0, 0.0});
  yarn["direction"] = list({0.0, 0.0, -2.0});
  yarn["pinned"] = list({0, -1});
  yarn["end_mass"] = 0.01;
  yarn["weibull_modulus"] = 10.0;
  yarn["seed"] = 7;
  const YarnSpec spec = loadYarnSpec(yarnParam(yarn), kNoPresets);
  EXPECT_EQ(spec.name, "weak");
  EXPECT_EQ(spec.material.name, "inline");
  EXPECT_DOUBLE_EQ(spec.material.density, 1500.0);
  EXPECT_DOUBLE_EQ(spec.material.curve.breakingStress(), 3.0e8);
  EXPECT_DOUBLE_EQ(spec.radius, 1.0e-4);
  EXPECT_EQ(spec.num_vertices, 5);
  EXPECT_DOUBLE_EQ(spec.start.x(), 0.1);
  EXPECT_DOUBLE_EQ(spec.direction.z(), -2.0);
  EXPECT_EQ(spec.pinned, (std::vector<int>{0, -1}));
  EXPECT_DOUBLE_EQ(spec.end_mass, 0.01);
  EXPECT_DOUBLE_EQ(spec.strength_scatter.weibull_modulus, 10.0);
  EXPECT_EQ(spec.strength_scatter.seed, 7ULL);
}

TEST(YarnSpecLoader, LoadsStrengthScatterAsACoefficientOfVariation) {
  XmlRpc::XmlRpcValue yarn = validYarn();
  yarn["strength_cv"] = 0.08;
  EXPECT_DOUBLE_EQ(
      loadYarnSpec(yarnParam(yarn), kNoPresets).strength_scatter.coefficient_of_variation, 0.08);
  yarn["weibull_modulus"] = 10.0;
  EXPECT_NE(yarnLoadError(yarn).find("strength_cv"), std::string::npos) << yarnLoadError(yarn);
  yarn = validYarn();
  yarn["strength_cv"] = 1.5;
  EXPECT_NE(yarnLoadError(yarn).find("/node/yarns[0].strength_cv"), std::string::npos)
      << yarnLoadError(yarn);
}

TEST(YarnSpecLoader, LoadsTheGaugeLengthOfTheStrengthStatistics) {
  XmlRpc::XmlRpcValue yarn = validYarn();
  EXPECT_DOUBLE_EQ(loadYarnSpec(yarnParam(yarn), kNoPresets).strength_scatter.gauge_length, 0.5);
  yarn["gauge_length"] = 0.25;
  EXPECT_DOUBLE_EQ(loadYarnSpec(yarnParam(yarn), kNoPresets).strength_scatter.gauge_length, 0.25);
  yarn["gauge_length"] = 0.0;
  EXPECT_NE(yarnLoadError(yarn).find("/node/yarns[0].gauge_length"), std::string::npos)
      << yarnLoadError(yarn);
}

TEST(YarnSpecLoader, AcceptsIntegersForNumbers) {
  XmlRpc::XmlRpcValue yarn = validYarn();
  yarn["length"] = 1;
  EXPECT_DOUBLE_EQ(loadYarnSpec(yarnParam(yarn), kNoPresets).length, 1.0);
}

TEST(YarnSpecLoader, ErrorNamesParameterValueAndAllowedRange) {
  XmlRpc::XmlRpcValue yarn = validYarn();
  yarn["radius"] = -0.5;
  const std::string error = yarnLoadError(yarn);
  EXPECT_NE(error.find("/node/yarns[0].radius"), std::string::npos) << error;
  EXPECT_NE(error.find("-0.5"), std::string::npos) << error;
  EXPECT_NE(error.find("in [1e-07, 1] [m]"), std::string::npos) << error;
}

/// Eight parameter values inside the type's range but past the physical bounds, each of which
/// would poison the state: each is refused naming its parameter and the bound.
TEST(YarnSpecLoader, RefusesValuesPastThePhysicalBounds) {
  const std::vector<std::pair<std::string, XmlRpc::XmlRpcValue>> cases = {
      {"radius", 1.0e-200},
      {"radius", 1.0e300},
      {"length", 1.0e-300},
      {"length", 1.0e300},
      {"start", list({1.0e308, 0.0, 0.0})},
      {"direction", list({1.0e300, 0.0, 0.0})},
      {"end_mass", 1.0e300},
      {"weibull_modulus", 1.0e-300},
      {"tex", 1.0e300},
  };
  for (const auto& [key, value] : cases) {
    XmlRpc::XmlRpcValue yarn = validYarn();
    if (key == "tex") yarn = withoutKey(yarn, "radius");
    yarn[key] = value;
    const std::string error = yarnLoadError(yarn);
    EXPECT_NE(error.find("/node/yarns[0]." + key), std::string::npos) << key << ": " << error;
  }
  XmlRpc::XmlRpcValue far = validYarn();  // start in bounds, but the end 1e4 m past them
  far["start"] = list({9.0e3, 0.0, 0.0});
  far["direction"] = list({1.0, 0.0, 0.0});
  far["length"] = 2.0e3;
  EXPECT_NE(yarnLoadError(far).find("/node/yarns[0].length"), std::string::npos)
      << yarnLoadError(far);
  XmlRpc::XmlRpcValue fine = validYarn();  // segments under 1 um
  fine["length"] = 1.0e-3;
  fine["num_vertices"] = 10000;
  EXPECT_NE(yarnLoadError(fine).find("num_vertices"), std::string::npos) << yarnLoadError(fine);
}

TEST(YarnSpecLoader, StartAndDirectionAreRequired) {
  for (const char* key : {"start", "direction"}) {
    XmlRpc::XmlRpcValue yarn = validYarn();
    yarn = withoutKey(yarn, key);
    EXPECT_NE(yarnLoadError(yarn).find(std::string("key '") + key + "'"), std::string::npos)
        << yarnLoadError(yarn);
  }
}

TEST(YarnSpecLoader, IntegralDoubleIsShownAsADouble) {
  // "seed = 0: expected an integer" contradicted itself: the value was 0.0.
  XmlRpc::XmlRpcValue yarn = validYarn();
  yarn["seed"] = 0.0;
  EXPECT_NE(yarnLoadError(yarn).find("seed = 0.0: expected an integer"), std::string::npos)
      << yarnLoadError(yarn);
}

TEST(YarnSpecLoader, RejectsWrongTypes) {
  XmlRpc::XmlRpcValue yarn = validYarn();
  yarn["num_vertices"] = 2.5;
  EXPECT_NE(yarnLoadError(yarn).find("num_vertices"), std::string::npos);
  yarn = validYarn();
  yarn["name"] = 3;
  EXPECT_NE(yarnLoadError(yarn).find("name"), std::string::npos);
  yarn = validYarn();
  yarn["start"] = list({0.0, 1.0});
  EXPECT_NE(yarnLoadError(yarn).find("start"), std::string::npos);
}

TEST(YarnSpecLoader, RejectsUnknownKeysListingTheAllowedOnes) {
  XmlRpc::XmlRpcValue yarn = validYarn();
  yarn["lenght"] = 0.1;
  const std::string error = yarnLoadError(yarn);
  EXPECT_NE(error.find("unknown key 'lenght'"), std::string::npos) << error;
  EXPECT_NE(error.find("length"), std::string::npos) << error;
}

TEST(YarnSpecLoader, RejectsPinnedIndicesOutOfRange) {
  XmlRpc::XmlRpcValue yarn = validYarn();
  yarn["pinned"] = list({0, 5});
  EXPECT_NE(yarnLoadError(yarn).find("[-5, 4]"), std::string::npos);
  yarn["pinned"] = list({-6});
  EXPECT_NE(yarnLoadError(yarn).find("pinned"), std::string::npos);
  yarn["pinned"] = list({-5, 4});
  EXPECT_EQ(yarnLoadError(yarn), "");
}

TEST(YarnSpecLoader, TexSizesTheYarnInsteadOfRadius) {
  XmlRpc::XmlRpcValue yarn = validYarn();
  yarn["tex"] = 20.0;
  EXPECT_NE(yarnLoadError(yarn).find("either radius"), std::string::npos);
  yarn = validYarn();
  yarn["packing_fraction"] = 0.5;
  EXPECT_NE(yarnLoadError(yarn).find("packing_fraction"), std::string::npos);
}

TEST(YarnSpecLoader, RejectsZeroDirection) {
  XmlRpc::XmlRpcValue yarn = validYarn();
  yarn["direction"] = list({0.0, 0.0, 0.0});
  EXPECT_NE(yarnLoadError(yarn).find("direction"), std::string::npos);
}

TEST(MaterialLoader, RefusesDensityCurveAndViscosityPastTheBounds) {
  XmlRpc::XmlRpcValue material = inlineMaterial();
  material["density"] = 1.0e-300;
  XmlRpc::XmlRpcValue yarn = validYarn();
  yarn["material"] = material;
  EXPECT_NE(yarnLoadError(yarn).find("material.density"), std::string::npos) << yarnLoadError(yarn);
  material = inlineMaterial();
  material["plastic_viscosity"] = 1.0e300;
  yarn["material"] = material;
  EXPECT_NE(yarnLoadError(yarn).find("plastic_viscosity"), std::string::npos)
      << yarnLoadError(yarn);
  material = inlineMaterial();
  material["stress_strain"] =
      list({list({0.0, 0.0}), list({1.0e-300, 1.0e8}), list({0.05, 3.0e8})});
  yarn["material"] = material;
  EXPECT_NE(yarnLoadError(yarn).find("stress_strain"), std::string::npos) << yarnLoadError(yarn);
}

TEST(MaterialLoader, RefusesACurveThatStiffensAfterYield) {
  // config/materials.yaml: every segment after the yield point must be less steep than E.
  XmlRpc::XmlRpcValue material = inlineMaterial();
  material["stress_strain"] = list({list({0.0, 0.0}), list({0.01, 1.0e8}), list({0.02, 5.0e8})});
  XmlRpc::XmlRpcValue yarn = validYarn();
  yarn["material"] = material;
  const std::string error = yarnLoadError(yarn);
  EXPECT_NE(error.find("material.stress_strain"), std::string::npos) << error;
  EXPECT_NE(error.find("less steep"), std::string::npos) << error;
}

TEST(MaterialLoader, LooksUpPresetsByName) {
  XmlRpc::XmlRpcValue presets;
  presets["cotton"] = inlineMaterial();
  presets["cotton"]["source"] = "a book";
  presets["cotton"]["rate_sensitivity"] = 0.05;
  const ParamValue preset_param("/node/materials", presets);
  const Material material =
      loadMaterial(ParamValue("/node/yarns[0].material", "cotton"), preset_param);
  EXPECT_EQ(material.name, "cotton");
  EXPECT_DOUBLE_EQ(material.rate_sensitivity, 0.05);

  try {
    loadMaterial(ParamValue("/node/yarns[0].material", "silk"), preset_param);
    FAIL() << "unknown preset accepted";
  } catch (const ParameterError& e) {
    const std::string error = e.what();
    EXPECT_NE(error.find("'silk'"), std::string::npos) << error;
    EXPECT_NE(error.find("(cotton)"), std::string::npos) << error;
  }
}

TEST(MaterialLoader, RejectsInvalidCurvesWithTheCoreReason) {
  XmlRpc::XmlRpcValue material = inlineMaterial();
  material["stress_strain"] = list({list({0.0, 0.0}), list({0.02, 1.0e8}), list({0.01, 2.0e8})});
  try {
    loadMaterial(ParamValue("/node/yarns[0].material", material), kNoPresets);
    FAIL() << "non-monotonic curve accepted";
  } catch (const ParameterError& e) {
    const std::string error = e.what();
    EXPECT_NE(error.find("/node/yarns[0].material.stress_strain"), std::string::npos) << error;
    EXPECT_NE(error.find("increasing"), std::string::npos) << error;
  }
}

TEST(MaterialLoader, RejectsMissingDensityAndUnknownKeys) {
  XmlRpc::XmlRpcValue material;
  material["stress_strain"] = curve();
  EXPECT_THROW(loadMaterial(ParamValue("/m", material), kNoPresets), ParameterError);
  material = inlineMaterial();
  material["modulus"] = 1.0e9;
  EXPECT_THROW(loadMaterial(ParamValue("/m", material), kNoPresets), ParameterError);
}

TEST(MaterialLoader, AcceptsTheReplacedPlasticViscosityOnlyAsZero) {
  XmlRpc::XmlRpcValue material = inlineMaterial();
  material["plastic_viscosity"] = 0.0;
  EXPECT_EQ(loadMaterial(ParamValue("/m", material), kNoPresets).rate_sensitivity, 0.0);
  material["plastic_viscosity"] = 5.0e9;
  try {
    loadMaterial(ParamValue("/m", material), kNoPresets);
    FAIL() << "plastic_viscosity > 0 accepted";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("rate_sensitivity"), std::string::npos) << e.what();
  }
  material = inlineMaterial();
  material["rate_sensitivity"] = 0.5;  // above the largest accepted, 0.25
  EXPECT_THROW(loadMaterial(ParamValue("/m", material), kNoPresets), ParameterError);
}

TEST(ParamValue, HintsAtYamlNumbersReadAsStrings) {
  try {
    ParamValue("/node/time_step", "1e-3").positiveNumber("s");
    FAIL() << "string accepted as a number";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("signed exponent"), std::string::npos) << e.what();
  }
}

TEST(ParamValue, RejectsNonFiniteNumbers) {
  EXPECT_THROW(ParamValue("/x", std::numeric_limits<double>::infinity()).nonNegativeNumber(""),
               ParameterError);
  EXPECT_THROW(ParamValue("/x", std::nan("")).number(0.0, 1.0, ""), ParameterError);
  EXPECT_DOUBLE_EQ(ParamValue("/x", 0.5).number(0.0, 1.0, ""), 0.5);
}

/// A fabric near the 1e4 m bound: origin (0, 9990, 0) [m], weft 20 m along +y, warp 30 m along
/// (1, -1, 0): its far corner is within the bound, its weft corner (0, 10010, 0) is not.
XmlRpc::XmlRpcValue fabricWithAFarCorner() {
  XmlRpc::XmlRpcValue family;
  family["material"] = testing::inlineMaterial();
  family["radius"] = 1.0e-4;
  XmlRpc::XmlRpcValue fabric;
  fabric["name"] = "patch";
  fabric["warp_length"] = 30.0;
  fabric["weft_length"] = 20.0;
  fabric["ends"] = 4;
  fabric["picks"] = 4;
  fabric["origin"] = list({0.0, 9990.0, 0.0});
  fabric["warp_direction"] = list({1.0, -1.0, 0.0});
  fabric["weft_direction"] = list({0.0, 1.0, 0.0});
  fabric["warp"] = family;
  fabric["weft"] = family;
  return fabric;
}

TEST(FabricSpecLoader, EveryCornerMustLieWithinTheBound) {
  const XmlRpc::XmlRpcValue fabric = fabricWithAFarCorner();
  const std::string error =
      parameterErrorOf([&] { loadFabricSpec(ParamValue("/node/fabrics[0]", fabric), kNoPresets); });
  EXPECT_NE(error.find("/node/fabrics[0].warp_length"), std::string::npos) << error;
  EXPECT_NE(error.find("every corner"), std::string::npos) << error;
  XmlRpc::XmlRpcValue inside = fabric;
  inside["weft_length"] = 5.0;  // weft corner (0, 9995, 0)
  EXPECT_NO_THROW(loadFabricSpec(ParamValue("/node/fabrics[0]", inside), kNoPresets));
}

}  // namespace
}  // namespace ros_layer
}  // namespace yarn_tearing
