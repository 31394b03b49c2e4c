#include "yarn_tearing/ros/marker_builder.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

#include "yarn_tearing/ros/geometry_conversion.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

constexpr int kSegmentsId = 0;
constexpr int kVerticesId = 1;
constexpr int kBreaksId = 2;
constexpr int kLabelId = 3;
constexpr int kMeshId = 0;             ///< in the fabric's own namespace
constexpr double kLabelHeight = 0.01;  ///< [m] height of the yarn-name text
constexpr double kVertexScale = 1.5;   ///< vertex sphere diameter / segment width
constexpr double kBreakScale = 4.0;    ///< break cube edge / segment width

std_msgs::ColorRGBA rgba(double r, double g, double b) {
  std_msgs::ColorRGBA color;
  color.r = static_cast<float>(r);
  color.g = static_cast<float>(g);
  color.b = static_cast<float>(b);
  color.a = 1.0F;
  return color;
}

/// Unbleached cotton, as lit face-on.
const std_msgs::ColorRGBA kClothColor = rgba(0.85, 0.78, 0.62);

/// The cloth's colour on a triangle of (unnormalised) normal `normal`, lit the same from either
/// side: RViz draws a TRIANGLE_LIST with per-vertex colours unlit, so the shading is baked in as
/// ambient + diffuse |n . l| from a fixed light above and in front (l in the world frame).
std_msgs::ColorRGBA shadedCloth(const Eigen::Vector3d& normal) {
  constexpr double kAmbient = 0.45;  ///< [-] share of the colour on a face edge-on to the light
  const Eigen::Vector3d light = Eigen::Vector3d(0.4, -0.3, 0.87).normalized();
  const double length = normal.norm();
  const double facing = length > 0.0 ? std::abs(normal.dot(light)) / length : 1.0;
  const double shade = kAmbient + (1.0 - kAmbient) * facing;
  return rgba(shade * kClothColor.r, shade * kClothColor.g, shade * kClothColor.b);
}

bool isFabricWeft(const Yarn& yarn) {
  return yarn.fabric >= 0 && yarn.family == FabricFamily::kWeft;
}

}  // namespace

std_msgs::ColorRGBA stressColor(double stress_ratio) {
  const double ratio = std::isfinite(stress_ratio) ? std::clamp(stress_ratio, 0.0, 1.0) : 1.0;
  // Hue 240 deg (blue) -> 0 deg (red) at full saturation and value, in sextants of 60 deg.
  const double hue = 4.0 * (1.0 - ratio);
  const double rising = hue - std::floor(hue);
  switch (static_cast<int>(std::floor(hue))) {
    case 0:
      return rgba(1.0, rising, 0.0);  // red -> yellow
    case 1:
      return rgba(1.0 - rising, 1.0, 0.0);  // yellow -> green
    case 2:
      return rgba(0.0, 1.0, rising);  // green -> cyan
    case 3:
      return rgba(0.0, 1.0 - rising, 1.0);  // cyan -> blue
    default:
      return rgba(0.0, 0.0, 1.0);  // blue
  }
}

MarkerBuilder::MarkerBuilder(std::string frame_id, double min_width)
    : frame_id_(std::move(frame_id)), min_width_(min_width) {}

void MarkerBuilder::addBreak(std::size_t yarn, const Eigen::Vector3d& position) {
  if (breaks_.size() <= yarn) {
    breaks_.resize(yarn + 1);
  }
  breaks_[yarn].push_back(position);
}

void MarkerBuilder::clearBreaks() { breaks_.clear(); }

visualization_msgs::MarkerArray MarkerBuilder::build(const Scene& scene, const ros::Time& stamp) {
  visualization_msgs::MarkerArray array;
  if (first_build_) {
    visualization_msgs::Marker clear;
    clear.header.frame_id = frame_id_;
    clear.header.stamp = stamp;
    clear.action = visualization_msgs::Marker::DELETEALL;
    array.markers.push_back(clear);
    first_build_ = false;
  }
  for (std::size_t y = 0; y < scene.yarns.size(); ++y) {
    const Yarn& yarn = scene.yarns[y];
    const double width = std::max(2.0 * yarn.radius, min_width_);
    array.markers.push_back(segments(scene, yarn, width, stamp));
    // A fabric's vertices are its warp's (its weft group shares them).
    if (!isFabricWeft(yarn)) array.markers.push_back(vertices(scene, yarn, width, stamp));
    array.markers.push_back(breaks(y, yarn, width, stamp));
  }
  for (const Fabric& fabric : scene.fabrics) array.markers.push_back(mesh(scene, fabric, stamp));
  for (const Yarn& yarn : scene.yarns) {
    if (!isFabricWeft(yarn)) array.markers.push_back(label(scene, yarn, stamp));
  }
  for (visualization_msgs::Marker& marker : array.markers) {
    if (marker.action == visualization_msgs::Marker::ADD && marker.points.empty() &&
        marker.type != visualization_msgs::Marker::TEXT_VIEW_FACING) {
      marker.action = visualization_msgs::Marker::DELETE;
    }
  }
  return array;
}

visualization_msgs::Marker MarkerBuilder::baseMarker(const Yarn& yarn, int id, int type,
                                                     double width, const ros::Time& stamp) const {
  visualization_msgs::Marker marker;
  marker.header.frame_id = frame_id_;
  marker.header.stamp = stamp;
  marker.ns = yarn.name;
  marker.id = id;
  marker.type = type;
  marker.action = visualization_msgs::Marker::ADD;
  marker.pose.orientation.w = 1.0;
  marker.scale.x = width;
  marker.scale.y = width;
  marker.scale.z = width;
  marker.color = rgba(1.0, 1.0, 1.0);
  return marker;
}

visualization_msgs::Marker MarkerBuilder::segments(const Scene& scene, const Yarn& yarn,
                                                   double width, const ros::Time& stamp) const {
  visualization_msgs::Marker marker =
      baseMarker(yarn, kSegmentsId, visualization_msgs::Marker::LINE_LIST, width, stamp);
  const EdgeSet& edges = scene.edges;
  const double breaking_stress = yarn.material.curve.breakingStress();
  for (std::uint32_t e = yarn.first_edge; e < yarn.first_edge + yarn.num_edges; ++e) {
    if (!edges.intact(e)) {
      continue;
    }
    const std_msgs::ColorRGBA color = stressColor(edges.stress[e] / breaking_stress);
    marker.points.push_back(toPoint(scene.vertices.position[edges.vertex_a[e]]));
    marker.points.push_back(toPoint(scene.vertices.position[edges.vertex_b[e]]));
    marker.colors.push_back(color);
    marker.colors.push_back(color);
  }
  return marker;
}

visualization_msgs::Marker MarkerBuilder::vertices(const Scene& scene, const Yarn& yarn,
                                                   double width, const ros::Time& stamp) const {
  visualization_msgs::Marker marker = baseMarker(
      yarn, kVerticesId, visualization_msgs::Marker::SPHERE_LIST, kVertexScale * width, stamp);
  for (std::uint32_t v = yarn.first_vertex; v < yarn.first_vertex + yarn.num_vertices; ++v) {
    marker.points.push_back(toPoint(scene.vertices.position[v]));
    marker.colors.push_back(scene.vertices.isSupport(v) ? rgba(1.0, 0.5, 0.0)
                                                        : rgba(0.6, 0.6, 0.6));
  }
  return marker;
}

visualization_msgs::Marker MarkerBuilder::label(const Scene& scene, const Yarn& yarn,
                                                const ros::Time& stamp) const {
  visualization_msgs::Marker marker =
      baseMarker(yarn, kLabelId, visualization_msgs::Marker::TEXT_VIEW_FACING, kLabelHeight, stamp);
  // A fabric is labelled once, by its own name (at its warp group's marker).
  marker.text =
      yarn.fabric >= 0 ? scene.fabrics.at(static_cast<std::size_t>(yarn.fabric)).name : yarn.name;
  marker.pose.position = toPoint(scene.vertices.position[yarn.first_vertex] +
                                 Eigen::Vector3d(0.0, 0.0, 1.5 * kLabelHeight));
  return marker;
}

visualization_msgs::Marker MarkerBuilder::mesh(const Scene& scene, const Fabric& fabric,
                                               const ros::Time& stamp) const {
  visualization_msgs::Marker marker;
  marker.header.frame_id = frame_id_;
  marker.header.stamp = stamp;
  marker.ns = fabric.name;
  marker.id = kMeshId;
  marker.type = visualization_msgs::Marker::TRIANGLE_LIST;
  marker.action = visualization_msgs::Marker::ADD;
  marker.pose.orientation.w = 1.0;
  marker.scale.x = 1.0;
  marker.scale.y = 1.0;
  marker.scale.z = 1.0;
  marker.color = kClothColor;
  const std::vector<Eigen::Vector3d>& x = scene.vertices.position;
  for (const FabricCell& cell : fabric.cells) {
    const bool intact = std::all_of(cell.edge.begin(), cell.edge.end(),
                                    [&](std::uint32_t e) { return scene.edges.intact(e); });
    if (!intact) continue;
    for (const std::array<int, 3>& triangle : {std::array<int, 3>{0, 1, 3}, {0, 3, 2}}) {
      const std::array<Eigen::Vector3d, 3> p = {
          x[cell.corner[triangle[0]]], x[cell.corner[triangle[1]]], x[cell.corner[triangle[2]]]};
      const std_msgs::ColorRGBA color = shadedCloth((p[1] - p[0]).cross(p[2] - p[0]));
      for (const Eigen::Vector3d& point : p) {
        marker.points.push_back(toPoint(point));
        marker.colors.push_back(color);
      }
    }
  }
  return marker;
}

visualization_msgs::Marker MarkerBuilder::breaks(std::size_t yarn_index, const Yarn& yarn,
                                                 double width, const ros::Time& stamp) const {
  visualization_msgs::Marker marker = baseMarker(
      yarn, kBreaksId, visualization_msgs::Marker::CUBE_LIST, kBreakScale * width, stamp);
  marker.color = rgba(1.0, 0.0, 1.0);
  if (yarn_index < breaks_.size()) {
    for (const Eigen::Vector3d& position : breaks_[yarn_index]) {
      marker.points.push_back(toPoint(position));
    }
  }
  return marker;
}

}  // namespace ros_layer
}  // namespace yarn_tearing
