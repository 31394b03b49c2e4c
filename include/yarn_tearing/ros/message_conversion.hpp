#pragma once

#include <ros/time.h>
#include <yarn_tearing/BreakEvent.h>

#include <string>

#include "yarn_tearing/FabricStateArray.h"
#include "yarn_tearing/YarnStateArray.h"
#include "yarn_tearing/core/model/scene.hpp"
#include "yarn_tearing/core/simulation/simulator.hpp"
#include "yarn_tearing/core/tearing/tear_event.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// The simulated instant `simulated_time` [s] as a ros::Time (for /clock; simulated time starts
/// at 0).
ros::Time simulatedStamp(double simulated_time);

/// State of every yarn (not the warp and weft of fabrics: toFabricStateArray), with per-yarn local
/// vertex and edge indices; positions, velocities and support forces are in `frame_id`;
/// header.stamp = `stamp` (see StampClock), sim_time = the simulator's time.
YarnStateArray toYarnStateArray(const Simulator& simulator, const std::string& frame_id,
                                const ros::Time& stamp);

/// State of every fabric (vertex index row * ends + column; segments warp first, then weft, each
/// labelled with family, yarn and segment), in `frame_id`, stamped as toYarnStateArray.
FabricStateArray toFabricStateArray(const Simulator& simulator, const std::string& frame_id,
                                    const ros::Time& stamp);

/// One break event (a fabric's also names fabric, family, yarn and segment); header.stamp = `stamp`
/// (see StampClock), sim_time = the simulated time of the break, position in `frame_id`.
BreakEvent toBreakEventMsg(const TearEvent& event, const Scene& scene, const std::string& frame_id,
                           const ros::Time& stamp);

}  // namespace ros_layer
}  // namespace yarn_tearing
