#pragma once

#include <Eigen/Core>
#include <vector>

#include "yarn_tearing/core/contact/contact_set.hpp"

namespace yarn_tearing {

/// The derivative of a sliding segment point's friction impulse, as it enters the Newton
/// matrix's vertex rows (-d impulse / dx, [kg]): block xy is row vertex x, column vertex y
/// (a and b the segment's vertices).
struct SlidingFrictionStiffness {
  Eigen::Matrix3d aa;
  Eigen::Matrix3d ab;
  Eigen::Matrix3d ba;
  Eigen::Matrix3d bb;
};

/// A segment point of contact `c` that slides along its tangents with the impulse
/// m_n sigma(x), sigma = sum_k slide[k] tau_k (`slide` [-] = +-mu along a sliding tangent, 0
/// along a sticking one), shared (1 - t, t) between its vertices: sigma turns with the segment
/// (tau_0 = P e / |P e|, P = I - n n^T, e = x_b - x_a, tau_1 = n x tau_0) and with the surface
/// under the point (d n = H dp), and t moves along a segment lying on a round solid
/// (ContactSet::closestPointTurn). The derivative is taken at the current m_n, as the edges'
/// geometric stiffness is at their current multipliers. False where there is none (a vertex
/// contact, no push, a segment along the normal).
bool slidingFrictionStiffness(const ContactSet& contacts, const Contact& c,
                              const double (&slide)[Contact::kFrictionDirections],
                              const std::vector<Eigen::Vector3d>& position,
                              SlidingFrictionStiffness& blocks);

/// The part of a sticking friction row's gradient that comes from its tangent turning: the row
/// is C_k = -tau_k(x) . s, s = p - anchor the point's slip over the step [m], and
/// dC_k = -tau_k . dp - s . d tau_k; this returns -s . d tau_k / dx_a and / dx_b [-] (tau_k turning
/// with the segment and with the surface under the point, at fixed t, as in
/// slidingFrictionStiffness). False where there is none (a vertex contact, a segment along the
/// normal).
bool stickingRowTurn(const ContactSet& contacts, const Contact& c, int k,
                     const Eigen::Vector3d& slip, const std::vector<Eigen::Vector3d>& position,
                     Eigen::Vector3d& on_a, Eigen::Vector3d& on_b);

}  // namespace yarn_tearing
