#include "yarn_tearing/ros/simulation_config.hpp"

#include <ros/console.h>
#include <ros/param.h>

#include <algorithm>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include "yarn_tearing/core/contact/deep_overlap.hpp"
#include "yarn_tearing/core/model/scene.hpp"
#include "yarn_tearing/ros/fabric_spec_loader.hpp"
#include "yarn_tearing/ros/param_value.hpp"
#include "yarn_tearing/ros/parameter_bounds.hpp"
#include "yarn_tearing/ros/parameter_error.hpp"
#include "yarn_tearing/ros/unknown_parameters.hpp"
#include "yarn_tearing/ros/yarn_spec_loader.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

namespace bounds = parameter_bounds;

/// Reads the private parameters of one node; missing parameters keep their defaults.
class PrivateParams {
 public:
  explicit PrivateParams(const ros::NodeHandle& nh) : nh_(nh) {}

  std::optional<ParamValue> get(const std::string& key) const {
    asked_.insert(key);
    XmlRpc::XmlRpcValue value;
    if (!nh_.getParam(key, value)) {
      return std::nullopt;
    }
    return ParamValue(nh_.resolveName(key), value);
  }

  ParamValue required(const std::string& key, const std::string& allowed) const {
    std::optional<ParamValue> value = get(key);
    if (!value) {
      throw ParameterError("missing parameter " + nh_.resolveName(key) + ": expected " + allowed);
    }
    return *value;
  }

  /// Every key asked for so far: the keys the node knows.
  const std::set<std::string>& askedKeys() const { return asked_; }

  template <typename Read>
  void read(const std::string& key, Read read_value) const {
    if (std::optional<ParamValue> value = get(key)) {
      read_value(*value);
    }
  }

 private:
  const ros::NodeHandle& nh_;
  mutable std::set<std::string> asked_;
};

/// Keys of the private namespace that are not start parameters but belong to the node.
const std::set<std::string> kOtherKnownKeys = {
    "paused",  // dynamic_reconfigure (cfg/YarnTearing.cfg) keeps it beside the start parameters
};

/// Warns about each key of the private namespace the node does not read (a misspelling would
/// otherwise be silently ignored), naming the nearest known key.
void warnUnknownKeys(const ros::NodeHandle& private_nh, std::set<std::string> known) {
  known.insert(kOtherKnownKeys.begin(), kOtherKnownKeys.end());
  std::vector<std::string> names;
  if (!ros::param::getParamNames(names)) {
    return;
  }
  for (const std::string& warning :
       unknownParameterWarnings(names, private_nh.getNamespace(), known)) {
    ROS_WARN("%s", warning.c_str());
  }
}

NodeSettings loadNodeSettings(const PrivateParams& params) {
  NodeSettings node;
  params.read("frame_id", [&](const ParamValue& v) { node.frame_id = v.string(false); });
  params.read("real_time_factor", [&](const ParamValue& v) {
    node.real_time_factor = v.number(0.0, bounds::kMaxRealTimeFactor, "");
  });
  params.read("publish_rate", [&](const ParamValue& v) {
    node.publish_rate = v.number(bounds::kMinPublishRate, bounds::kMaxPublishRate, "Hz");
  });
  params.read("publish_clock", [&](const ParamValue& v) { node.publish_clock = v.boolean(); });
  params.read("max_lag", [&](const ParamValue& v) { node.max_lag = v.number(1.0e-3, 10.0, "s"); });
  params.read("marker_width",
              [&](const ParamValue& v) { node.marker_width = v.number(1.0e-6, 1.0, "m"); });
  params.read("frame_timeout", [&](const ParamValue& v) {
    node.frame_timeout = v.number(0.0, bounds::kMaxFrameTimeout, "s");
  });
  params.read("max_extrapolation", [&](const ParamValue& v) {
    node.max_extrapolation = v.number(0.0, bounds::kMaxExtrapolation, "s");
  });
  return node;
}

SimulationParameters loadPhysics(const PrivateParams& params) {
  SimulationParameters p;
  params.read("time_step", [&](const ParamValue& v) { p.time_step = v.number(1.0e-7, 0.1, "s"); });
  params.read("gravity", [&](const ParamValue& v) {
    p.gravity = v.boundedVector3(bounds::kMaxGravity, "m/s^2");
  });
  params.read("tension_estimate", [&](const ParamValue& v) {
    p.tension_source =
        v.choice<TensionSource>({{"constraint_force", TensionSource::kConstraintForce},
                                 {"least_squares", TensionSource::kLeastSquares}});
  });
  params.read("regularization", [&](const ParamValue& v) {
    // [0, 1), as the core and doc/node.md say (number() checks a closed range)
    const std::string allowed = "a finite number in [0, 1)";
    double regularization = 1.0;
    try {
      regularization = v.number(0.0, 1.0, "");
    } catch (const ParameterError&) {
      v.fail(allowed);
    }
    if (regularization >= 1.0) {
      v.fail(allowed);
    }
    p.regularization = regularization;
  });
  params.read("air_damping",
              [&](const ParamValue& v) { p.air_damping = v.nonNegativeNumber("N*s/m^2"); });
  params.read("soft_spring_ratio",
              [&](const ParamValue& v) { p.soft_spring_ratio = v.number(0.0, 1.0, ""); });
  params.read("constraint_tolerance",
              [&](const ParamValue& v) { p.constraint_tolerance = v.number(1.0e-15, 0.1, ""); });
  params.read("max_projection_iterations",
              [&](const ParamValue& v) { p.max_projection_iterations = v.integer(1, 10000); });
  params.read("projection_method", [&](const ParamValue& v) {
    p.projection_method =
        v.choice<ProjectionMethod>({{"fast_projection", ProjectionMethod::kFastProjection},
                                    {"gauss_seidel", ProjectionMethod::kGaussSeidel}});
  });
  params.read("breaking_enabled", [&](const ParamValue& v) { p.breaking_enabled = v.boolean(); });
  params.read("recoil_substeps",
              [&](const ParamValue& v) { p.recoil_substeps = v.integer(1, 10000); });
  params.read("threads", [&](const ParamValue& v) { p.threads = v.integer(1, 1024); });
  try {
    p.validate();
  } catch (const std::invalid_argument& e) {
    throw ParameterError(std::string("invalid simulation parameters: ") + e.what());
  }
  return p;
}

/// ~yarns and ~fabrics: at least one yarn or fabric, unique names, within the scene budget; the
/// scene they build.
Scene loadBodies(const PrivateParams& params, SimulationConfig& config) {
  const std::string allowed = "a list of yarns (see config/default.yaml)";
  const std::optional<ParamValue> yarns = params.get("yarns");
  const std::optional<ParamValue> fabrics = params.get("fabrics");
  if (!yarns && !fabrics) {
    params.required("yarns", allowed + ", or ~fabrics (config/fabric.yaml)");
  }
  const ParamValue presets =
      params.get("materials").value_or(ParamValue("~materials", XmlRpc::XmlRpcValue()));
  std::set<std::string> names;
  std::size_t elements = 0;         // vertices + edges
  std::size_t fabric_vertices = 0;  // ends x picks over the fabrics
  if (yarns) {
    const std::vector<ParamValue> entries = yarns->elements();
    if (entries.empty() && !fabrics) yarns->fail("a non-empty " + allowed);
    for (const ParamValue& entry : entries) {
      config.yarns.push_back(loadYarnSpec(entry, presets));
      if (!names.insert(config.yarns.back().name).second) {
        entry.member("name").fail("a name that no other yarn or fabric has");
      }
      elements += 2 * static_cast<std::size_t>(config.yarns.back().num_vertices) - 1;
    }
  }
  if (fabrics) {
    const std::vector<ParamValue> entries = fabrics->elements();
    if (entries.empty() && config.yarns.empty()) {
      fabrics->fail("a non-empty list of fabrics (see config/fabric.yaml)");
    }
    for (const ParamValue& entry : entries) {
      config.fabrics.push_back(loadFabricSpec(entry, presets));
      const FabricSpec& spec = config.fabrics.back();
      if (!names.insert(spec.name).second) {
        entry.member("name").fail("a name that no other yarn or fabric has");
      }
      const auto ends = static_cast<std::size_t>(spec.ends);
      const auto picks = static_cast<std::size_t>(spec.picks);
      elements += 3 * ends * picks - ends - picks;
      fabric_vertices += ends * picks;
      if (fabric_vertices > bounds::kFabricVertexBudget) {
        fabrics->fail(
            "fabrics of at most " + std::to_string(bounds::kFabricVertexBudget) +
            " vertices (ends x picks) in all (the fabric budget, 256 x 256); these have " +
            std::to_string(fabric_vertices) + " or more");
      }
      if (elements > bounds::kSceneBudget) break;
    }
  }
  if (elements > bounds::kSceneBudget) {
    (yarns ? *yarns : *fabrics)
        .fail("yarns and fabrics of at most " + std::to_string(bounds::kSceneBudget) +
              " vertices + edges in all (the scene budget); these have " +
              std::to_string(elements) + " or more");
  }
  try {
    return buildScene(config.yarns, config.fabrics);
  } catch (const std::exception& e) {
    (yarns ? *yarns : *fabrics)
        .fail(std::string("yarns and fabrics that build a scene (") + e.what() + ")");
  }
}

/// ~obstacles (optional): unique names; a fixed one clear of `scene`'s yarns (at most half a
/// segment into them, findDeepOverlap).
void loadObstacles(const PrivateParams& params, const Scene& scene, SimulationConfig& config) {
  const std::optional<ParamValue> obstacles = params.get("obstacles");
  if (!obstacles) return;
  std::set<std::string> names;
  for (const ParamValue& entry : obstacles->elements()) {
    config.obstacles.push_back(loadObstacleSpec(entry));
    const ObstacleSpec& spec = config.obstacles.back();
    if (!names.insert(spec.obstacle.name).second) {
      entry.member("name").fail("a name that no other obstacle has");
    }
    if (spec.attached()) continue;  // placed where its frame is, once it resolves
    if (const std::optional<DeepOverlap> overlap = findDeepOverlap(spec.obstacle, scene)) {
      (entry.has("position") ? entry.member("position") : entry)
          .fail("a pose clear of the yarns and fabrics: " +
                describeDeepOverlap(*overlap, spec.obstacle, scene));
    }
  }
}

/// Air damping is explicit: c * dt must stay below the lightest yarn's mass per length, or the drag
/// overshoots (reverses the velocity) and grows without bound.
void requireStableDamping(const PrivateParams& params, const SimulationConfig& config) {
  const double limit = maxStableAirDamping(config);  // [N*s/m^2]
  if (!(config.parameters.air_damping < limit)) {
    std::ostringstream allowed;
    allowed << "a number in [0, " << limit
            << ") [N*s/m^2]: below the lightest yarn's mass per length / time_step (explicit drag)";
    params.get("air_damping")->fail(allowed.str());
  }
}

}  // namespace

double maxStableAirDamping(const SimulationConfig& config) {
  double lightest = std::numeric_limits<double>::infinity();  // [kg/m]
  for (const YarnSpec& spec : config.yarns) {
    lightest = std::min(lightest, spec.linearDensity());
  }
  // A fabric vertex's mass per damped length lies between its two families' linear densities.
  for (const FabricSpec& spec : config.fabrics) {
    lightest = std::min({lightest, spec.warp.linearDensity(), spec.weft.linearDensity()});
  }
  return lightest / config.parameters.time_step;
}

SimulationConfig loadSimulationConfig(const ros::NodeHandle& private_nh) {
  const PrivateParams params(private_nh);
  SimulationConfig config;
  config.node = loadNodeSettings(params);
  config.parameters = loadPhysics(params);
  const Scene scene = loadBodies(params, config);
  loadObstacles(params, scene, config);
  requireStableDamping(params, config);
  warnUnknownKeys(private_nh, params.askedKeys());
  return config;
}

}  // namespace ros_layer
}  // namespace yarn_tearing
