#include "yarn_tearing/core/contact/sliding_friction_stiffness.hpp"

namespace yarn_tearing {
namespace {

/// [v]x, the matrix of the cross product v x.
Eigen::Matrix3d crossMatrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

/// How a contact's friction tangents turn with its segment e = x_b - x_a and with the surface
/// under its point p = (1 - t) x_a + t x_b: d tau_k = turn[k] de + roll[k] dp [1/m].
struct TangentTurn {
  Eigen::Matrix3d turn[Contact::kFrictionDirections];
  Eigen::Matrix3d roll[Contact::kFrictionDirections];
};

/// False for a vertex contact, or a segment along the normal (its tangents do not turn with it).
bool tangentTurn(const ContactSet& contacts, const Contact& c,
                 const std::vector<Eigen::Vector3d>& position, TangentTurn& result) {
  if (c.a == c.b) return false;
  const Eigen::Vector3d& n = c.normal;
  const Eigen::Vector3d& tau = c.tangent[0];
  const Eigen::Vector3d axis = position[c.b] - position[c.a];
  const double across = (axis - n.dot(axis) * n).norm();
  if (!(across > 1e-9 * axis.norm())) return false;
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  // tau_0 turns with e, d tau_1 = n x d tau_0 ...
  result.turn[0] =
      (1.0 / across) * (identity - tau * tau.transpose()) * (identity - n * n.transpose());
  result.turn[1] = crossMatrix(n) * result.turn[0];
  // ... and with the normal: d tau_0 = -n tau_0^T H dp, d tau_1 = d n x tau_0 = -[tau_0]x H dp.
  const Eigen::Matrix3d curvature = contacts.curvature(c, position);
  result.roll[0] = -n * tau.transpose() * curvature;
  result.roll[1] = -crossMatrix(tau) * curvature;
  return true;
}

}  // namespace

bool slidingFrictionStiffness(const ContactSet& contacts, const Contact& c,
                              const double (&slide)[Contact::kFrictionDirections],
                              const std::vector<Eigen::Vector3d>& position,
                              SlidingFrictionStiffness& blocks) {
  // Without it the Newton steps of a sliding wrap converged only linearly (0.85-0.9 per Newton
  // step at 2 pi, mu 0.3, 1e-5 s substeps), where m_n / l is of the order of a vertex's mass.
  TangentTurn tangents;
  if (!(c.normal_multiplier > 0.0) || !tangentTurn(contacts, c, position, tangents)) return false;
  const Eigen::Vector3d axis = position[c.b] - position[c.a];
  const double wa = 1.0 - c.t;
  const double wb = c.t;
  const double m = c.normal_multiplier;
  // d(m_n sigma) = turn de + roll dp, sigma = sum_k slide[k] tau_k.
  const Eigen::Matrix3d turn = m * (slide[0] * tangents.turn[0] + slide[1] * tangents.turn[1]);
  const Eigen::Matrix3d roll = m * (slide[0] * tangents.roll[0] + slide[1] * tangents.roll[1]);
  // The impulse on a is wa m_n sigma, on b wb m_n sigma; the rows take its negative.
  blocks.aa = wa * turn - wa * wa * roll;
  blocks.ab = -wa * turn - wa * wb * roll;
  blocks.ba = wb * turn - wb * wa * roll;
  blocks.bb = -wb * turn - wb * wb * roll;
  // The closest point moving along the segment, dt = -derivative^T (dx_a, dx_b) / second: the
  // shares (1 - t, t) move, and the point rolls along the surface by e dt.
  Eigen::Matrix<double, 6, 1> derivative;
  double second = 0.0;
  if (!contacts.closestPointTurn(c, position, derivative, second)) return true;
  Eigen::Vector3d sigma = Eigen::Vector3d::Zero();
  for (int k = 0; k < Contact::kFrictionDirections; ++k) sigma += slide[k] * c.tangent[k];
  const Eigen::Vector3d shifted = m * sigma;   // d(impulse on b) / dt = -d(impulse on a) / dt
  const Eigen::Vector3d rolled = roll * axis;  // d(m_n sigma) / dt through the rolling point
  const Eigen::Matrix<double, 6, 1> dt = -derivative / second;
  blocks.aa += (shifted - wa * rolled) * dt.head<3>().transpose();
  blocks.ab += (shifted - wa * rolled) * dt.tail<3>().transpose();
  blocks.ba += (-shifted - wb * rolled) * dt.head<3>().transpose();
  blocks.bb += (-shifted - wb * rolled) * dt.tail<3>().transpose();
  return true;
}

bool stickingRowTurn(const ContactSet& contacts, const Contact& c, int k,
                     const Eigen::Vector3d& slip, const std::vector<Eigen::Vector3d>& position,
                     Eigen::Vector3d& on_a, Eigen::Vector3d& on_b) {
  // d tau_k = turn_k de + roll_k dp (de = dx_b - dx_a, dp = (1 - t) dx_a + t dx_b).
  TangentTurn tangents;
  if (!tangentTurn(contacts, c, position, tangents)) return false;
  const Eigen::Vector3d turned = tangents.turn[k].transpose() * slip;
  const Eigen::Vector3d rolled = tangents.roll[k].transpose() * slip;
  on_a = turned - (1.0 - c.t) * rolled;
  on_b = -turned - c.t * rolled;
  return true;
}

}  // namespace yarn_tearing
