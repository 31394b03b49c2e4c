#include "yarn_tearing/core/simulation/simulator.hpp"

#include <algorithm>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "yarn_tearing/core/contact/deep_overlap.hpp"
#include "yarn_tearing/core/forces/explicit_forces.hpp"
#include "yarn_tearing/core/forces/fabric_shear.hpp"
#include "yarn_tearing/core/material/material_response.hpp"
#include "yarn_tearing/core/material/strength_scatter.hpp"
#include "yarn_tearing/core/simulation/held_target_limit.hpp"
#include "yarn_tearing/core/simulation/nonfinite_recovery.hpp"
#include "yarn_tearing/core/simulation/recoil_region.hpp"
#include "yarn_tearing/core/simulation/recoil_wave.hpp"
#include "yarn_tearing/core/simulation/release_run.hpp"

namespace yarn_tearing {
namespace {

/// After a tear's pieces have unloaded, each substep of the rest of the step is this many times
/// the last [-] (about log4(recoil_substeps) substeps to the step's end): few substeps, yet a
/// growth slow enough for the Newton steps of a still-recoiling piece to converge
/// (doc/method.md, "Recoil substeps").
constexpr double kRecoilGrowth = 4.0;

/// An unconverged step without obstacles is retried in substeps of this fraction of it, and a
/// substep that does not converge in substeps of this fraction of itself, down to the fine one
/// [-]: a step too long for its projection is mostly a little too long (doc/method.md,
/// "Substeps for an unconverged step").
constexpr double kRetryShrink = 4.0;
/// After a retried substep converges, the next may be this many times as long [-].
constexpr double kRetryGrowth = 2.0;

/// Fine substeps [-] a fabric's release wave must take to unload the torn yarn's loaded run for
/// the recoil substeps to keep any of its motion; within fewer (a trouser tear's tip in a 2 mm
/// weave at Δt = 1e-3) they damp it as one step does, at several times its cost
/// (doc/method.md, "A fabric's short release").
constexpr double kResolvedReleaseSubsteps = 2.0;

/// A local recoil takes the yarn within this many times the elastic wave's travel, c t, of a
/// tear [-] ...
constexpr double kRecoilReach = 1.25;
/// ... and this many of the torn edge's rest lengths beyond [-] through the release wave: its
/// explicit substeps carry a front one edge a substep, up to c t / 0.97, and the boundary
/// vertices move on unaffected while their neighbours recoil.
constexpr double kRecoilMarginEdges = 24.0;

void requireVertex(const Scene& scene, std::uint32_t vertex) {
  if (vertex >= scene.vertices.size()) {
    throw std::out_of_range("vertex " + std::to_string(vertex) + " out of range [0, " +
                            std::to_string(scene.vertices.size()) + ")");
  }
}

void validateScene(const Scene& scene) {
  const VertexSet& v = scene.vertices;
  const EdgeSet& e = scene.edges;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!(v.mass[i] > 0.0) || !v.position[i].allFinite() || v.yarn[i] >= scene.yarns.size()) {
      throw std::invalid_argument("scene vertex " + std::to_string(i) +
                                  " needs a mass > 0, a finite position and an existing yarn");
    }
  }
  for (std::size_t i = 0; i < e.size(); ++i) {
    const bool ok = e.vertex_a[i] < v.size() && e.vertex_b[i] < v.size() &&
                    e.vertex_a[i] != e.vertex_b[i] && e.yarn[i] < scene.yarns.size() &&
                    e.original_rest_length[i] > 0.0 && e.area[i] > 0.0 &&
                    e.strength_factor[i] > 0.0;
    if (!ok) {
      throw std::invalid_argument("scene edge " + std::to_string(i) +
                                  " needs two distinct existing vertices, an existing yarn and a "
                                  "rest length, area and strength factor > 0");
    }
  }
}

}  // namespace

Simulator::Simulator(const SimulationParameters& parameters, const std::vector<YarnSpec>& yarns,
                     const std::vector<FabricSpec>& fabrics)
    : parameters_(parameters), initial_scene_(buildScene(yarns, fabrics)) {
  parameters_.validate();
  reset();
}

Simulator::Simulator(const SimulationParameters& parameters, Scene scene)
    : parameters_(parameters), initial_scene_(std::move(scene)) {
  parameters_.validate();
  validateScene(initial_scene_);
  assignBreakingStrains(initial_scene_.yarns, initial_scene_.edges);
  reset();
}

void Simulator::setParameters(const SimulationParameters& parameters) {
  parameters.validate();
  parameters_ = parameters;
  applySolverSwitches();
}

void Simulator::applySolverSwitches() {
  work_.gram.forceGeneralPath(parameters_.force_general_solver);
  work_.gram.forceDirectSolves(parameters_.force_direct_solves);
  work_.projection.forceFullNewtonSystems(parameters_.force_full_newton_systems);
  work_.projection.forceFreshFactorizations(parameters_.force_fresh_factorizations);
  work_.gram.setThreads(parameters_.threads);
  work_.projection.setThreads(parameters_.threads);
}

void Simulator::reset() {
  scene_ = initial_scene_;
  resetWorkspace();
  support_force_.assign(scene_.vertices.size(), Eigen::Vector3d::Zero());
  pending_events_.clear();
  health_ = StepHealth{};
  time_ = 0.0;
  step_count_ = 0;
  recoil_pending_ = false;
  torn_edges_.clear();
}

void Simulator::resetWorkspace() {
  const std::size_t n = scene_.vertices.size();
  work_.projection = LengthConstraintProjection{};
  work_.estimator = TensionEstimator{};
  work_.tearing = Tearing{};  // its unloading times belong to the state left behind
  work_.force.assign(n, Eigen::Vector3d::Zero());
  work_.start_position.assign(n, Eigen::Vector3d::Zero());
  work_.start_velocity.assign(n, Eigen::Vector3d::Zero());
  work_.constraint_tension.assign(scene_.edges.size(), 0.0);
  work_.gram.setTopology(scene_.edges, n);
  work_.contacts.clear();
  work_.vertex_radius.resize(n);
  for (std::size_t v = 0; v < n; ++v) {
    work_.vertex_radius[v] = scene_.yarns[scene_.vertices.yarn[v]].radius;
  }
  contact_wrench_.assign(obstacles_.size(), ContactWrench{});
  applySolverSwitches();
}

void Simulator::step() {
  const std::vector<RequestedTarget> requested = limitHeldTargets(scene_, parameters_.time_step);
  const bool can_substep = parameters_.recoil_substeps > 1;
  std::vector<std::uint32_t> torn;
  torn.swap(torn_edges_);
  if (recoil_pending_ && can_substep) {
    // A yarn's release wave, else recoil substeps, else (a fabric's short release) one step,
    // substepped after all should it not converge.
    const bool local = parameters_.local_recoil && recoilLocally(torn);
    if (!local && (releaseResolvedBySubsteps(torn) || !advance(true))) advanceInSubsteps(true);
  } else if (!advance(can_substep)) {
    advanceInSubsteps(false);  // the whole step did not converge: taken again in substeps
  }
  restoreHeldTargets(requested, scene_);
  ++step_count_;
}

bool Simulator::advance(bool undo_if_unconverged) {
  accumulateForces();          // 1
  predictPositions();          // 2
  projectLengthConstraints();  // 3
  if (undo_if_unconverged && !health_.projection_converged) {
    undoPrediction();
    return false;
  }
  estimateTensions();  // 4
  updateMaterial();    // 5
  time_ += parameters_.time_step;
  const std::size_t events_before = pending_events_.size();
  tear();  // 6
  restoreNonFiniteYarns(events_before);
  recoil_pending_ = health_.breaks > 0 && health_.restored_yarns.empty();
  previous_pose_.clear();
  for (const Obstacle& o : obstacles_) previous_pose_.push_back(o.pose);
  health_.substeps = 1;
  health_.substepped_vertices = 0;
  return true;
}

void Simulator::undoPrediction() {
  scene_.vertices.position = work_.start_position;
  scene_.vertices.velocity = work_.start_velocity;
  // The warm starts hold the unconverged solve; nothing else has changed yet (stages 4-6 have
  // not run, and the obstacles' previous poses are kept until a step completes).
  resetWorkspace();
}

void Simulator::restoreNonFiniteYarns(std::size_t first_event_of_step) {
  health_.restored_yarns = nonFiniteYarns(scene_, support_force_);
  if (health_.restored_yarns.empty()) return;
  for (std::uint32_t yarn : health_.restored_yarns) {
    restoreYarn(initial_scene_, yarn, scene_);
    for (std::size_t v = 0; v < scene_.vertices.size(); ++v) {
      if (scene_.vertices.yarn[v] == yarn) support_force_[v].setZero();
    }
    const auto of_yarn = [yarn](const TearEvent& event) { return event.yarn == yarn; };
    pending_events_.erase(
        std::remove_if(pending_events_.begin() + static_cast<std::ptrdiff_t>(first_event_of_step),
                       pending_events_.end(), of_yarn),
        pending_events_.end());
  }
  // The solvers' warm starts may hold the non-finite values of this step.
  resetWorkspace();
}

void Simulator::advanceInSubsteps(bool recoil) {
  VertexSet& vertices = scene_.vertices;
  step_target_ = vertices.kinematic_target;
  step_start_ = vertices.position;
  const double time_step = parameters_.time_step;
  const double start_time = time_;
  const double fine = time_step / parameters_.recoil_substeps;
  const double slack = 1.0e-6 * fine;  // round-off in the substeps' sum [s]
  StepHealth whole;                    // of the whole step: the worst of its substeps
  whole.projection_iterations = 0;
  bool tore = false;
  bool coarse_failed = false;
  double elapsed = 0.0;
  // A retry without a tear or obstacles: substeps shrinking while they do not converge, growing
  // while they do (with obstacles, whose friction states an undone substep forgets, fine ones).
  const bool retry_ladder = !recoil && obstacles_.empty();
  const double growth = recoil ? kRecoilGrowth : kRetryGrowth;
  // The next coarse substep's length [s]: after a tear, from the fine one up.
  double next = recoil ? 0.0 : time_step / kRetryShrink;
  int count = 0;
  while (elapsed < time_step - slack) {
    const double remaining = time_step - elapsed;
    // Once every torn piece has unloaded (the elastic wave has crossed it), substeps growing
    // geometrically to the step's end. One that does not converge is undone; then a retry's
    // ladder takes a quarter of it, a tear's recoil the rest of the step in fine substeps.
    const bool unloaded = time_ >= work_.tearing.unloadingEnd() - slack;
    const bool coarse = (recoil || retry_ladder) && unloaded && !coarse_failed;
    double h = coarse ? std::max(fine, next) : fine;
    if (remaining < h + 0.5 * h) h = remaining;
    setSubstepTargets((elapsed + h) / time_step);
    parameters_.time_step = h;
    work_.projection.forgetCorrection();
    if (!advance(coarse && h > fine + slack)) {
      if (retry_ladder) {
        next = h / kRetryShrink;
      } else {
        coarse_failed = true;
      }
      continue;
    }
    next = growth * h;
    elapsed += h;
    time_ = start_time + elapsed;
    ++count;
    accumulateHealth(health_, whole);
    tore = tore || recoil_pending_;
  }
  parameters_.time_step = time_step;
  vertices.kinematic_target = step_target_;
  work_.projection.forgetCorrection();  // a substep's, rescaled to a whole step
  time_ = start_time + time_step;
  std::sort(whole.restored_yarns.begin(), whole.restored_yarns.end());
  whole.restored_yarns.erase(std::unique(whole.restored_yarns.begin(), whole.restored_yarns.end()),
                             whole.restored_yarns.end());
  whole.substeps = count;
  whole.substepped_vertices = vertices.size();
  health_ = whole;
  recoil_pending_ = tore;
}

bool Simulator::releaseResolvedBySubsteps(const std::vector<std::uint32_t>& torn) const {
  const auto in_a_yarn = [this](std::uint32_t e) { return scene_.fabricOfEdge(e) < 0; };
  if (parameters_.substep_every_recoil || torn.empty() ||
      std::any_of(torn.begin(), torn.end(), in_a_yarn)) {
    return true;
  }
  const double fine = parameters_.time_step / parameters_.recoil_substeps;
  return releaseCrossingTime(scene_, work_.gram.incidence(), torn) >=
         kResolvedReleaseSubsteps * fine;
}

double Simulator::recoilReach(const std::vector<std::uint32_t>& torn, double duration) const {
  double reach = 0.0;
  for (std::uint32_t e : torn) {
    const double speed = scene_.yarns[scene_.edges.yarn[e]].material.waveSpeed();
    reach = std::max(reach, kRecoilReach * speed * duration +
                                kRecoilMarginEdges * scene_.edges.original_rest_length[e]);
  }
  return reach;
}

bool Simulator::recoilLocally(const std::vector<std::uint32_t>& torn) {
  if (torn.empty() || !obstacles_.empty()) return false;
  const RecoilRegion region =
      RecoilRegion::around(scene_, torn, recoilReach(torn, parameters_.time_step));
  if (!region.usable || 2 * region.vertices.size() > scene_.vertices.size()) return false;
  const Scene start = scene_;
  const Tearing start_tearing = work_.tearing;
  const std::vector<Eigen::Vector3d> start_support = support_force_;
  const std::size_t start_events = pending_events_.size();
  const double start_time = time_;
  const std::vector<Eigen::Vector3d> acceleration = startAccelerations(parameters_, start);
  const bool done = stepAroundRegion(region, start, acceleration) &&
                    propagateRecoilWave(region, torn, start, acceleration, start_tearing);
  if (done) return true;
  scene_ = start;
  resetWorkspace();
  work_.tearing = start_tearing;
  support_force_ = start_support;
  pending_events_.resize(start_events);
  torn_edges_.clear();  // what the undone step tore
  time_ = start_time;
  recoil_pending_ = true;
  return false;
}

bool Simulator::stepAroundRegion(const RecoilRegion& region, const Scene& start,
                                 const std::vector<Eigen::Vector3d>& acceleration) {
  VertexSet& vertices = scene_.vertices;
  for (std::uint32_t v : region.vertices) {
    if (vertices.motion[v] != VertexMotion::kFree) continue;
    vertices.motion[v] = VertexMotion::kKinematic;
    vertices.kinematic_target[v] =
        unaffectedPosition(start, acceleration, v, parameters_.time_step);
  }
  // The region's edges sit this step out: the wave takes them.
  for (std::uint32_t e : region.edges) scene_.edges.broken[e] = 1;
  const bool converged = advance(true);
  for (std::uint32_t e : region.edges) scene_.edges.broken[e] = 0;
  for (std::uint32_t v : region.vertices) {
    if (start.vertices.motion[v] != VertexMotion::kFree) continue;
    vertices.motion[v] = VertexMotion::kFree;
    vertices.kinematic_target[v] = start.vertices.kinematic_target[v];
    // The path's velocity at the step's end, not the step's mean (a boundary vertex keeps it).
    vertices.velocity[v] = start.vertices.velocity[v] + parameters_.time_step * acceleration[v];
    support_force_[v].setZero();
  }
  return converged && health_.breaks == 0 && health_.restored_yarns.empty();
}

Eigen::Vector3d Simulator::unaffectedPosition(const Scene& start,
                                              const std::vector<Eigen::Vector3d>& acceleration,
                                              std::uint32_t v, double elapsed) const {
  const VertexSet& vertices = start.vertices;
  if (vertices.motion[v] == VertexMotion::kPinned) return vertices.position[v];
  if (vertices.motion[v] == VertexMotion::kKinematic) {
    const double fraction = elapsed / parameters_.time_step;
    return vertices.position[v] + fraction * (vertices.kinematic_target[v] - vertices.position[v]);
  }
  return vertices.position[v] + elapsed * vertices.velocity[v] +
         (0.5 * elapsed * elapsed) * acceleration[v];
}

std::vector<double> Simulator::waveArrival(const RecoilRegion& region,
                                           const std::vector<std::uint32_t>& torn) const {
  const double infinite = std::numeric_limits<double>::infinity();
  std::vector<double> arrival(region.vertices.size(), infinite);
  for (std::size_t i = 0; i < region.vertices.size(); ++i) {
    if (region.boundary[i]) continue;
    for (std::uint32_t e : torn) {
      // The inverse of recoilReach(): when the reach from this tear covers the vertex.
      const double speed = scene_.yarns[scene_.edges.yarn[e]].material.waveSpeed();
      const double margin = kRecoilMarginEdges * scene_.edges.original_rest_length[e];
      arrival[i] = std::min(arrival[i],
                            std::max(0.0, (region.distance[i] - margin) / (kRecoilReach * speed)));
    }
  }
  return arrival;
}

bool Simulator::propagateRecoilWave(const RecoilRegion& region,
                                    const std::vector<std::uint32_t>& torn, const Scene& start,
                                    const std::vector<Eigen::Vector3d>& acceleration,
                                    const Tearing& start_tearing) {
  std::vector<Eigen::Vector3d> local_acceleration;
  for (std::uint32_t v : region.vertices) local_acceleration.push_back(acceleration[v]);
  std::optional<Simulator> built;
  try {
    built.emplace(parameters_, region.subScene(start));
  } catch (const std::invalid_argument&) {
    return false;  // a sub-scene that does not validate: the whole scene is substepped instead
  }
  Simulator& local = *built;
  local.work_.tearing = start_tearing.restrictedTo(region.vertices);
  local.time_ = time_ - parameters_.time_step;
  if (!local.advanceWave(waveArrival(region, torn), local_acceleration)) return false;
  if (local.health_.breaks > 0 || !local.health_.restored_yarns.empty()) return false;
  region.writeBack(local.scene_, scene_);
  for (std::size_t i = 0; i < region.vertices.size(); ++i) {
    if (!region.boundary[i]) support_force_[region.vertices[i]] = local.support_force_[i];
  }
  StepHealth whole = local.health_;
  accumulateHealth(health_, whole);  // the rest of the scene's step
  whole.substeps = local.health_.substeps;
  whole.substepped_vertices = region.vertices.size();
  health_ = whole;
  recoil_pending_ = false;
  return true;
}

bool Simulator::advanceWave(const std::vector<double>& arrival,
                            const std::vector<Eigen::Vector3d>& start_acceleration) {
  accumulateExternalForces(parameters_, scene_.vertices, work_.force);
  // The wave's springs are the whole edge: no soft spring of its own.
  std::fill(scene_.edges.spring_tension.begin(), scene_.edges.spring_tension.end(), 0.0);
  work_.start_position = scene_.vertices.position;
  work_.start_velocity = scene_.vertices.velocity;
  const RecoilWaveResult wave =
      integrateRecoilWave(parameters_, arrival, start_acceleration, parameters_.time_step, scene_,
                          work_.constraint_tension);
  if (!wave.completed) return false;
  health_ = StepHealth{};
  health_.projection_iterations = 0;
  estimateTensions();
  // The force balance over the whole step is no check on a wave resolved within it.
  health_.tension_residual = 0.0;
  updateMaterial();
  time_ += parameters_.time_step;
  const std::size_t events_before = pending_events_.size();
  tear();
  restoreNonFiniteYarns(events_before);
  health_.substeps = wave.substeps;
  return true;
}

void Simulator::setSubstepTargets(double fraction) {
  VertexSet& vertices = scene_.vertices;
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    if (vertices.motion[v] != VertexMotion::kKinematic) continue;
    vertices.kinematic_target[v] = step_start_[v] + fraction * (step_target_[v] - step_start_[v]);
  }
}

void Simulator::accumulateForces() {
  computeStretchLimits(scene_, parameters_, work_.stretch_limits);
  accumulateExplicitForces(parameters_, scene_.vertices, work_.stretch_limits.soft_spring,
                           scene_.edges, work_.force);
  accumulateShearForces(scene_, parameters_, work_.force);
  computeFlowLimits(scene_, work_.stretch_limits);  // after the soft springs' tensions
}

void Simulator::predictPositions() {
  work_.start_position = scene_.vertices.position;
  work_.start_velocity = scene_.vertices.velocity;
  yarn_tearing::predictPositions(work_.force, parameters_.time_step, scene_.vertices);
}

void Simulator::projectLengthConstraints() {
  VertexSet& vertices = scene_.vertices;
  EdgeSet& edges = scene_.edges;
  work_.contacts.clear();
  if (!obstacles_.empty()) {
    inverse_mass_.resize(vertices.size());
    for (std::size_t v = 0; v < vertices.size(); ++v) inverse_mass_[v] = vertices.inverseMass(v);
    ContactSet::Input input;
    input.obstacles = &obstacles_;
    input.previous_pose = &previous_pose_;
    input.start = &work_.start_position;
    input.predicted = &vertices.position;
    input.inverse_mass = &inverse_mass_;
    input.vertex_radius = &work_.vertex_radius;
    input.edges = &edges;
    work_.contacts.detect(input);
  }
  const ProjectionResult result =
      work_.projection.project(vertices.position, vertices, edges, work_.stretch_limits,
                               parameters_, work_.gram, &work_.contacts, &work_.start_position);
  applyContactForces();
  for (std::size_t e = 0; e < edges.size(); ++e) {
    work_.constraint_tension[e] = work_.projection.constraintForce(e);
  }
  health_.projection_iterations = result.iterations;
  health_.factorizations = result.factorizations;
  health_.analyses = result.analyses;
  health_.max_constraint_violation = result.max_violation;
  health_.projection_converged = result.converged;
  health_.force_mismatch = result.force_mismatch;
  health_.max_penetration = result.max_penetration;
  const double dt = parameters_.time_step;
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    if (vertices.motion[v] == VertexMotion::kFree) {
      vertices.velocity[v] = (vertices.position[v] - work_.start_position[v]) / dt;
    }
  }
}

void Simulator::applyContactForces() {
  for (ContactWrench& wrench : contact_wrench_) wrench = ContactWrench{};
  const double dt2 = parameters_.time_step * parameters_.time_step;
  const std::vector<Eigen::Vector3d>& x = scene_.vertices.position;
  for (const Contact& c : work_.contacts.contacts()) {
    const Eigen::Vector3d force = c.impulse() / dt2;  // on the yarn [N]
    // An external force of the step: the tension estimate's rows and the holders count it.
    work_.force[c.a] += (1.0 - c.t) * force;
    if (c.b != c.a) work_.force[c.b] += c.t * force;
    ContactWrench& wrench = contact_wrench_[c.obstacle];
    wrench.force -= force;
    wrench.torque -= (c.point(x) - obstacles_[c.obstacle].pose.translation()).cross(force);
  }
}

void Simulator::estimateTensions() {
  TensionEstimateInput input;
  input.vertices = &scene_.vertices;
  input.start_velocity = &work_.start_velocity;
  input.force = &work_.force;
  input.time_step = parameters_.time_step;
  input.regularization = parameters_.regularization;
  input.rows = parameters_.tension_rows;
  input.source = parameters_.tension_source;
  health_.tension_residual =
      work_.estimator.estimate(input, scene_.edges, work_.gram, work_.constraint_tension);

  // Total axial force, and what the supports feel: F_v + constraint pull - m a.
  const VertexSet& vertices = scene_.vertices;
  EdgeSet& edges = scene_.edges;
  const double dt = parameters_.time_step;
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    support_force_[v].setZero();
    if (!vertices.isSupport(v)) continue;
    support_force_[v] =
        work_.force[v] - vertices.mass[v] / dt * (vertices.velocity[v] - work_.start_velocity[v]);
  }
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!edges.intact(e)) continue;
    edges.tension[e] = work_.constraint_tension[e] + edges.spring_tension[e];
    const std::uint32_t a = edges.vertex_a[e];
    const std::uint32_t b = edges.vertex_b[e];
    if (!vertices.isSupport(a) && !vertices.isSupport(b)) continue;
    const Eigen::Vector3d d = vertices.position[b] - vertices.position[a];
    const double length = d.norm();
    if (!(length > 0.0)) continue;
    const Eigen::Vector3d pull = (work_.constraint_tension[e] / length) * d;
    if (vertices.isSupport(a)) support_force_[a] += pull;
    if (vertices.isSupport(b)) support_force_[b] -= pull;
  }
}

void Simulator::updateMaterial() {
  updateMaterialResponse(scene_.yarns, parameters_.time_step, scene_.edges);
}

void Simulator::tear() {
  health_.breaks = 0;
  if (!parameters_.breaking_enabled) return;
  const std::vector<std::uint32_t>& torn = work_.tearing.collect(scene_, time_);
  health_.breaks = static_cast<int>(torn.size());
  torn_edges_.insert(torn_edges_.end(), torn.begin(), torn.end());
  work_.tearing.apply(scene_, work_.start_velocity, time_, pending_events_);
}

void Simulator::setAppliedForce(std::uint32_t vertex, const Eigen::Vector3d& force) {
  requireVertex(scene_, vertex);
  if (!force.allFinite()) throw std::invalid_argument("applied force must be finite");
  scene_.vertices.applied_force[vertex] = force;
}

void Simulator::setKinematicTarget(std::uint32_t vertex, const Eigen::Vector3d& target) {
  requireVertex(scene_, vertex);
  if (!target.allFinite()) throw std::invalid_argument("kinematic target must be finite");
  scene_.vertices.motion[vertex] = VertexMotion::kKinematic;
  scene_.vertices.kinematic_target[vertex] = target;
}

void Simulator::setVelocity(std::uint32_t vertex, const Eigen::Vector3d& velocity) {
  requireVertex(scene_, vertex);
  if (!velocity.allFinite()) throw std::invalid_argument("velocity must be finite");
  if (scene_.vertices.motion[vertex] == VertexMotion::kFree) {
    scene_.vertices.velocity[vertex] = velocity;
  }
}

void Simulator::releaseVertex(std::uint32_t vertex) {
  requireVertex(scene_, vertex);
  if (scene_.vertices.motion[vertex] != VertexMotion::kKinematic) return;
  const bool was_pinned = initial_scene_.vertices.motion[vertex] == VertexMotion::kPinned;
  scene_.vertices.motion[vertex] = was_pinned ? VertexMotion::kPinned : VertexMotion::kFree;
  if (was_pinned) scene_.vertices.velocity[vertex].setZero();
}

void Simulator::setObstacles(const std::vector<Obstacle>& obstacles) {
  for (const Obstacle& o : obstacles) {
    o.validate();
    // One already in place stays unchecked: the contact has kept the yarns out of it.
    const auto in_place = [&o](const Obstacle& old) { return old.sameGeometry(o); };
    if (std::none_of(obstacles_.begin(), obstacles_.end(), in_place)) requireClearOfYarns(o);
  }
  // The same solids where they were (only their friction or names changed): the contacts keep
  // their friction states (a point new to a step is frictionless in its first Newton step,
  // which let a wrap whose friction was switched on slip 2.7 chords in that Newton step).
  bool same = obstacles.size() == obstacles_.size();
  for (std::size_t i = 0; i < obstacles.size() && same; ++i) {
    same = obstacles[i].sameGeometry(obstacles_[i]);
  }
  obstacles_ = obstacles;
  previous_pose_.clear();
  for (const Obstacle& o : obstacles_) previous_pose_.push_back(o.pose);
  contact_wrench_.assign(obstacles_.size(), ContactWrench{});
  if (!same) work_.contacts.clear();
}

void Simulator::setObstaclePose(std::size_t index, const Eigen::Isometry3d& pose) {
  if (index >= obstacles_.size()) {
    throw std::out_of_range("obstacle " + std::to_string(index) + " out of range [0, " +
                            std::to_string(obstacles_.size()) + ")");
  }
  Obstacle moved = obstacles_[index];
  moved.pose = pose;
  moved.validate();
  if (!moved.sameGeometry(obstacles_[index])) requireClearOfYarns(moved);
  obstacles_[index] = moved;
}

void Simulator::requireClearOfYarns(const Obstacle& obstacle) const {
  if (const std::optional<DeepOverlap> overlap = findDeepOverlap(obstacle, scene_)) {
    throw ObstacleThroughYarn(obstacle.name, describeDeepOverlap(*overlap, obstacle, scene_));
  }
}

std::vector<TearEvent> Simulator::takeTearEvents() {
  std::vector<TearEvent> events;
  events.swap(pending_events_);
  return events;
}

}  // namespace yarn_tearing
