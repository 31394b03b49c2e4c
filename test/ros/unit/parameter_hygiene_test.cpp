#include <gtest/gtest.h>

#include "yarn_tearing/ros/unknown_parameters.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

const std::set<std::string> kKnown = {"air_damping",  "frame_id",       "gravity", "materials",
                                      "publish_rate", "regularization", "yarns"};

TEST(UnknownParameters, NearestNameIsATypoAway) {
  EXPECT_EQ(nearestName("air_dampin", kKnown), "air_damping");
  EXPECT_EQ(nearestName("publish_rat", kKnown), "publish_rate");
  EXPECT_EQ(nearestName("regularisation", kKnown), "regularization");
  EXPECT_EQ(nearestName("colour", kKnown), "");  // no known key is a typo of it
}

TEST(UnknownParameters, WarnsOncePerUnknownKeyOfTheNamespace) {
  const std::vector<std::string> names = {
      "/yarn_tearing/air_dampin", "/yarn_tearing/frame_id",
      "/yarn_tearing/yarns",      "/yarn_tearing/materials/cotton/density",
      "/yarn_tearing/colour/red", "/yarn_tearing/colour/green",
      "/other_node/air_dampin",   "/yarn_tearing_other/x",
  };
  const std::vector<std::string> warnings =
      unknownParameterWarnings(names, "/yarn_tearing", kKnown);
  ASSERT_EQ(warnings.size(), 2U);
  EXPECT_EQ(warnings[0],
            "unknown parameter /yarn_tearing/air_dampin (ignored); did you mean 'air_damping'?");
  EXPECT_EQ(warnings[1], "unknown parameter /yarn_tearing/colour (ignored)");
}

}  // namespace
}  // namespace ros_layer
}  // namespace yarn_tearing
