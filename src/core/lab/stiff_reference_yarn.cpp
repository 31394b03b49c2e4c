#include "yarn_tearing/core/lab/stiff_reference_yarn.hpp"

#include <algorithm>
#include <cmath>

#include "yarn_tearing/core/model/scene.hpp"

namespace yarn_tearing {

StiffReferenceYarn::StiffReferenceYarn(const YarnSpec& spec, const Eigen::Vector3d& gravity,
                                       double stability_fraction)
    : gravity_(gravity) {
  const Scene scene = buildScene({spec});
  position_ = scene.vertices.position;
  mass_ = scene.vertices.mass;
  velocity_.assign(position_.size(), Eigen::Vector3d::Zero());
  force_.assign(position_.size(), Eigen::Vector3d::Zero());
  pinned_.resize(position_.size());
  cut_.assign(scene.edges.size(), false);
  for (std::size_t v = 0; v < position_.size(); ++v) pinned_[v] = scene.vertices.isSupport(v);
  rest_length_ = scene.edges.original_rest_length[0];
  stiffness_ = spec.material.curve.youngsModulus() * spec.area() / rest_length_;
  const double lightest = *std::min_element(mass_.begin(), mass_.end());
  const double omega_max = std::sqrt(4.0 * stiffness_ / lightest);
  time_step_ = stability_fraction * 2.0 / omega_max;
}

double StiffReferenceYarn::tension(std::size_t e) const {
  if (cut_[e]) return 0.0;
  const double length = (position_[e + 1] - position_[e]).norm();
  return std::max(0.0, stiffness_ * (length - rest_length_));
}

void StiffReferenceYarn::step(double dt) {
  for (std::size_t v = 0; v < position_.size(); ++v) force_[v] = mass_[v] * gravity_;
  for (std::size_t e = 0; e + 1 < position_.size(); ++e) {
    const Eigen::Vector3d d = position_[e + 1] - position_[e];
    const Eigen::Vector3d f = (tension(e) / d.norm()) * d;
    force_[e] += f;
    force_[e + 1] -= f;
  }
  for (std::size_t v = 0; v < position_.size(); ++v) {
    if (pinned_[v]) continue;
    velocity_[v] += (dt / mass_[v]) * force_[v];
    position_[v] += dt * velocity_[v];
  }
  time_ += dt;
}

void StiffReferenceYarn::setPositions(const std::vector<Eigen::Vector3d>& positions) {
  position_ = positions;
  for (Eigen::Vector3d& v : velocity_) v.setZero();
}

double StiffReferenceYarn::kineticEnergy() const {
  double energy = 0.0;
  for (std::size_t v = 0; v < position_.size(); ++v) {
    if (!pinned_[v]) energy += 0.5 * mass_[v] * velocity_[v].squaredNorm();
  }
  return energy;
}

void StiffReferenceYarn::advance(double duration) {
  const double end = time_ + duration;
  while (end - time_ > 1e-15) step(std::min(time_step_, end - time_));
}

}  // namespace yarn_tearing
