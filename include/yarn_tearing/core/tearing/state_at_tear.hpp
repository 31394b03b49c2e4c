#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "yarn_tearing/core/model/scene.hpp"
#include "yarn_tearing/core/tearing/tear_event.hpp"

namespace yarn_tearing {

/// The break event of an edge that tears now, reporting the edge's state at the tear.
///
/// The tension estimate of a step that tears can be far past what the edge carries (a grasp that
/// jumps, a force 1000 times the strength: the length stop is 10^6 times stiffer than the yarn),
/// so the event does not copy it. The rule:
/// - strain ε = min(|x_b − x_a| / L0 − 1, ε_b,e): the edge's own length, at most its breaking
///   strain (EdgeSet::breaking_strain: the curve's strain at its strength f·σ_b);
/// - stress σ = min(T_est / A, σ_c(ε)) and tension T = σ·A, where σ_c(ε) = max(0, min(E·(ε − ε_p),
///   curve(ε))) is what that strain carries: elastically from the plastic strain ε_p, at most the
///   loading curve; so σ ≤ the curve at the breaking strain (both times the edge's rate factor,
///   EdgeSet::rate_factor, 1 for a rate-independent material);
/// - plastic_strain = ε_p;
/// - strain_rate = d(|x_b − x_a| / L0)/dt = (v_b − v_a)·(x_b − x_a)/|x_b − x_a| / L0 [1/s] with
///   the ends' velocities v as the step began (`start_velocity`, per vertex [m/s]): the rate of
///   the edge's geometric strain it was loaded at (the tearing step itself may stop at the
///   breaking length part way), what a lab reads (crosshead speed over gauge length on a
///   uniform pull; the stress rate over the curve's tangent modulus on a force ramp).
/// On a slow pull the estimate and the length agree, and the event reports σ_b·A at ε_b.
/// `time` [s] is the simulated time of the event.
TearEvent tearEventOf(const Scene& scene, const std::vector<Eigen::Vector3d>& start_velocity,
                      std::size_t edge, double time);

}  // namespace yarn_tearing
