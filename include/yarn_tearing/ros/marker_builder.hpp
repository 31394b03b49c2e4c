#pragma once

#include <ros/time.h>
#include <std_msgs/ColorRGBA.h>
#include <visualization_msgs/MarkerArray.h>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "yarn_tearing/core/model/scene.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// Colour of a stress ratio (stress / breaking stress [-], clamped to [0, 1]): the hue runs from
/// blue (0) over cyan, green and yellow to red (1).
std_msgs::ColorRGBA stressColor(double stress_ratio);

/// Builds yarn_markers. Per yarn (namespace = yarn name, fixed ids, identity orientation):
///   id 0 LINE_LIST   intact segments, each coloured by stress / breaking stress;
///   id 1 SPHERE_LIST vertices (supports orange, free ones grey);
///   id 2 CUBE_LIST   the positions where the yarn tore;
///   id 3 TEXT_VIEW_FACING the yarn's name, 1 cm high, 1.5 cm above its vertex 0 (after the
///        other markers of all yarns).
/// A fabric's warp and weft are drawn as two such yarns, '<fabric>/warp' and '<fabric>/weft'
/// (segments coloured by stress / breaking stress, breaks), its vertices and its label (the
/// fabric's name) once, in the warp's namespace; and per fabric (namespace = fabric name):
///   id 0 TRIANGLE_LIST the cloth, two triangles per cell whose four segments are intact, so torn
///        cells disappear.
/// A marker with no points (but the text) is sent as DELETE; the first array starts with one
/// DELETEALL (clears markers of an earlier run), later ones never do, so RViz does not flicker.
class MarkerBuilder {
 public:
  /// `frame_id`: frame of the scene; `min_width` [m]: smallest drawn segment width (yarns are
  /// drawn 2 r wide when that is larger).
  MarkerBuilder(std::string frame_id, double min_width);

  /// Records a break at `position` [m] of yarn `yarn` (index in the scene).
  void addBreak(std::size_t yarn, const Eigen::Vector3d& position);
  /// Forgets all breaks (after a reset).
  void clearBreaks();

  /// Markers of the whole scene, stamped `stamp`.
  visualization_msgs::MarkerArray build(const Scene& scene, const ros::Time& stamp);

 private:
  visualization_msgs::Marker baseMarker(const Yarn& yarn, int id, int type, double width,
                                        const ros::Time& stamp) const;
  visualization_msgs::Marker segments(const Scene& scene, const Yarn& yarn, double width,
                                      const ros::Time& stamp) const;
  visualization_msgs::Marker vertices(const Scene& scene, const Yarn& yarn, double width,
                                      const ros::Time& stamp) const;
  visualization_msgs::Marker label(const Scene& scene, const Yarn& yarn,
                                   const ros::Time& stamp) const;
  visualization_msgs::Marker mesh(const Scene& scene, const Fabric& fabric,
                                  const ros::Time& stamp) const;
  visualization_msgs::Marker breaks(std::size_t yarn_index, const Yarn& yarn, double width,
                                    const ros::Time& stamp) const;

  std::string frame_id_;
  double min_width_;                                  ///< [m]
  std::vector<std::vector<Eigen::Vector3d>> breaks_;  ///< per yarn, positions [m]
  bool first_build_ = true;
};

}  // namespace ros_layer
}  // namespace yarn_tearing
