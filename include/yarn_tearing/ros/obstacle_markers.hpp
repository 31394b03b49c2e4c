#pragma once

#include <ros/time.h>
#include <visualization_msgs/Marker.h>

#include <string>
#include <vector>

#include "yarn_tearing/core/contact/obstacle.hpp"
#include "yarn_tearing/core/simulation/simulator.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// Markers of one obstacle for yarn_markers, in namespace "obstacles/<name>", frame `frame_id`:
///   id 0 the solid: box CUBE, sphere SPHERE, capsule CYLINDER (its straight part), plane a thin
///        CUBE (kPlaneMarkerSize square, kPlaneMarkerThickness thick, its top face the surface);
///   ids 1, 2 capsule only: SPHEREs closing its ends;
///   id 3 ARROW of the contact force the yarns exert on it (`wrench`), its tip on the force's line
///        of action where it is closest to the obstacle's origin, its length logarithmic in the
///        force (kArrowLengthPerDecade per decade above kArrowSmallestForce, from
///        kArrowShortest to kArrowLongest); sent as DELETE while the force is zero.
/// Solids are grey and half transparent, the arrow magenta.
std::vector<visualization_msgs::Marker> obstacleMarkers(const Obstacle& obstacle,
                                                        const ContactWrench& wrench,
                                                        const std::string& frame_id,
                                                        const ros::Time& stamp);

constexpr double kPlaneMarkerSize = 2.0;         ///< [m] side of the square drawn for a plane
constexpr double kPlaneMarkerThickness = 0.001;  ///< [m]
constexpr double kArrowSmallestForce = 1.0e-4;   ///< [N] drawn kArrowShortest long
constexpr double kArrowLengthPerDecade = 0.02;   ///< [m] more length per tenfold force
constexpr double kArrowShortest = 0.01;          ///< [m]
constexpr double kArrowLongest = 0.2;            ///< [m]

}  // namespace ros_layer
}  // namespace yarn_tearing
