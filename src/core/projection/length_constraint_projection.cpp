#include "yarn_tearing/core/projection/length_constraint_projection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace yarn_tearing {

ProjectionResult LengthConstraintProjection::project(
    std::vector<Eigen::Vector3d>& position, const VertexSet& vertices, const EdgeSet& edges,
    const EdgeStretchLimits& limits, const SimulationParameters& parameters, EdgeGramSolver& gram,
    ContactSet* contacts, const std::vector<Eigen::Vector3d>* step_start) {
  time_step2_ = parameters.time_step * parameters.time_step;
  inverse_mass_.resize(vertices.size());
  for (std::size_t v = 0; v < vertices.size(); ++v) inverse_mass_[v] = vertices.inverseMass(v);
  const std::size_t q = edges.size();
  stretch_state_.reset(edges, limits, parameters.time_step);
  direction_.resize(q);
  residual_.resize(q);
  limit_.resize(q);
  step_.resize(q);
  active_.resize(q);
  candidate_.resize(q);
  target_.resize(q);
  product_.resize(q);
  stretch_.resize(q);
  multiplier_.assign(q, 0.0);
  // Contacts are rows of the Newton steps only: Gauss-Seidel is left to contact-free scenes.
  if (contacts != nullptr && contacts->empty()) contacts = nullptr;
  const long factorizations = newton_.factorizations();
  const long analyses = newton_.analyses();
  ProjectionResult resting;
  if (contacts != nullptr && projectContactsFast(position, vertices, edges, limits, parameters,
                                                 gram, *contacts, resting)) {
    resting.factorizations = static_cast<int>(newton_.factorizations() - factorizations);
    resting.analyses = static_cast<int>(newton_.analyses() - analyses);
    return resting;
  }
  ProjectionResult result =
      parameters.projection_method == ProjectionMethod::kGaussSeidel && contacts == nullptr
          ? projectGaussSeidel(position, edges, parameters)
          : projectFast(position, edges, parameters, gram, contacts, step_start);
  result.factorizations = static_cast<int>(newton_.factorizations() - factorizations);
  result.analyses = static_cast<int>(newton_.analyses() - analyses);
  holdEdgesBetweenSupports(position, edges);
  return result;
}

bool LengthConstraintProjection::projectContactsFast(
    std::vector<Eigen::Vector3d>& position, const VertexSet& vertices, const EdgeSet& edges,
    const EdgeStretchLimits& limits, const SimulationParameters& parameters, EdgeGramSolver& gram,
    ContactSet& contacts, ProjectionResult& result) {
  if (parameters.projection_method != ProjectionMethod::kFastProjection) return false;
  // Vertices on frictionless faces move within them, a mobility the rows do not know: where a
  // row would move one, it is taken without them (their contacts as rows).
  resting_.select(contacts, inverse_mass_, true);
  bool selected = fast_rows_.select(contacts, resting_.handled(), inverse_mass_) &&
                  !fast_rows_.touches(resting_.onFaceMask());
  if (!selected && resting_.anyOnFace()) {
    resting_.select(contacts, inverse_mass_, false);
    selected = fast_rows_.select(contacts, resting_.handled(), inverse_mass_);
  }
  if (!selected) return false;
  // What a failed guess must give back to the full solve: the prediction and the warm starts.
  resting_fallback_.position = position;
  resting_fallback_.last_multiplier = last_multiplier_;
  resting_fallback_.was_taut = was_taut_;
  resting_fallback_.was_flowing = was_flowing_;
  resting_fallback_.last_stiffness = last_stiffness_;
  resting_fallback_.last_time_step2 = last_time_step2_;
  resting_fallback_.newton_first_next = newton_first_next_;
  // The stuck vertices become supports where they stuck; final directions everywhere, as the
  // full solve with contacts.
  resting_.hold(position, inverse_mass_);
  fast_contacts_ = fast_rows_.empty() ? nullptr : &contacts;
  on_faces_ = resting_.anyOnFace();
  result = projectFast(position, edges, parameters, gram, nullptr, nullptr);
  fast_contacts_ = nullptr;
  on_faces_ = false;
  holdEdgesBetweenSupports(position, edges);
  for (std::size_t v = 0; v < vertices.size(); ++v) inverse_mass_[v] = vertices.inverseMass(v);
  // With rows, the fast iterations have linearized every contact at the final positions.
  if (result.converged && fast_rows_.frictionHolds(contacts) &&
      resting_.accept(contacts, position, resting_fallback_.position, inverse_mass_, edges,
                      multiplier_, parameters.constraint_tolerance, !fast_rows_.empty())) {
    result.max_penetration = contacts.maxPenetration();
    return true;
  }
  resting_.restore(contacts);
  position = resting_fallback_.position;
  last_multiplier_.swap(resting_fallback_.last_multiplier);
  was_taut_.swap(resting_fallback_.was_taut);
  was_flowing_.swap(resting_fallback_.was_flowing);
  last_stiffness_.swap(resting_fallback_.last_stiffness);
  last_time_step2_ = resting_fallback_.last_time_step2;
  newton_first_next_ = resting_fallback_.newton_first_next;
  stretch_state_.reset(edges, limits, parameters.time_step);
  multiplier_.assign(edges.size(), 0.0);
  return false;
}

void LengthConstraintProjection::linearizeFastRows(const std::vector<Eigen::Vector3d>& position,
                                                   ProjectionResult& result) {
  fast_contacts_->linearize(position);
  fast_rows_.linearize(*fast_contacts_, position);
  result.max_penetration = fast_contacts_->maxPenetration();
}

void LengthConstraintProjection::holdEdgesBetweenSupports(
    const std::vector<Eigen::Vector3d>& position, const EdgeSet& edges) {
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const std::uint32_t a = edges.vertex_a[e];
    const std::uint32_t b = edges.vertex_b[e];
    if (!edges.intact(e) || inverse_mass_[a] + inverse_mass_[b] > 0.0) continue;
    multiplier_[e] =
        stretch_state_.multiplierAtLength(edges, e, (position[b] - position[a]).norm());
  }
}

bool LengthConstraintProjection::newtonFirst(std::size_t num_edges) {
  if (!newton_first_next_ || last_multiplier_.size() != num_edges) return false;
  // (omega dt)^2 and the multipliers (forces times dt^2) scale with dt^2: rescaled for a step of
  // another length (recoil substeps).
  const double scale = time_step2_ / last_time_step2_;
  const bool stiff = std::any_of(last_stiffness_.begin(), last_stiffness_.end(),
                                 [scale](double stiffness) { return scale * stiffness > 1.0; });
  if (!stiff) return false;
  for (std::size_t e = 0; e < num_edges; ++e) multiplier_[e] = scale * last_multiplier_[e];
  return true;
}

void LengthConstraintProjection::computeSidewaysStiffness(const EdgeSet& edges) {
  // (omega dt)^2 = w_v sum_e m_e / l_e (m_e = T_e dt^2): a vertex on taut edges, pulled sideways,
  // is pulled back with stiffness sum_e T_e / l_e.
  sideways_stiffness_.assign(inverse_mass_.size(), 0.0);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!candidate_[e]) continue;
    const double stiffness = multiplier_[e] / limit_[e];
    sideways_stiffness_[edges.vertex_a[e]] += inverse_mass_[edges.vertex_a[e]] * stiffness;
    sideways_stiffness_[edges.vertex_b[e]] += inverse_mass_[edges.vertex_b[e]] * stiffness;
  }
}

void LengthConstraintProjection::chooseCorrectionDirections(
    const std::vector<Eigen::Vector3d>& step_start, const EdgeSet& edges) {
  // Only in a piece that a support holds: an edge whose ends take different directions exerts
  // a small net force (its tension times its turn in the step), which the support takes up
  // there; a free piece keeps its momentum exactly on final directions.
  const std::size_t n = inverse_mass_.size();
  if (last_stiffness_.size() != n) {
    last_stiffness_.assign(n, std::numeric_limits<double>::infinity());
  }
  // (omega dt)^2 scales with dt^2: a step of another length (recoil substeps) rescales it.
  const double limit = kStartDirectionStiffness * last_time_step2_ / time_step2_;
  updateHeldVertices(edges);
  // A support does not move: which direction its correction would take does not matter.
  const auto slow = [&](std::uint32_t v) {
    return inverse_mass_[v] > 0.0 && held_vertex_[v] != 0 && last_stiffness_[v] <= limit;
  };
  start_direction_.resize(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!candidate_[e]) continue;
    const std::uint32_t a = edges.vertex_a[e];
    const std::uint32_t b = edges.vertex_b[e];
    // The start direction is read only where an end takes it.
    const bool slow_a = slow(a);
    const bool slow_b = slow(b);
    if (!slow_a && !slow_b) continue;
    const Eigen::Vector3d d = step_start[b] - step_start[a];
    const double length = d.norm();
    if (!(length > 0.0)) continue;
    start_direction_[e] = d / length;
    if (start_direction_[e].dot(direction_[e]) < kStartDirectionCosine) continue;
    start_at_a_[e] = slow_a ? 1 : 0;
    start_at_b_[e] = slow_b ? 1 : 0;
    any_start_direction_ = any_start_direction_ || start_at_a_[e] || start_at_b_[e];
  }
}

std::uint64_t LengthConstraintProjection::piecesSignature(const EdgeSet& edges) const {
  // The pieces change only where an edge tore or a vertex was pinned, grasped or released.
  std::uint64_t intact = 0;
  std::uint64_t supports = 0;
  std::uint64_t support_sum = 0;
  for (std::size_t e = 0; e < edges.size(); ++e) intact += edges.intact(e) ? 1 : 0;
  for (std::size_t v = 0; v < inverse_mass_.size(); ++v) {
    const bool support = inverse_mass_[v] == 0.0;
    supports += support ? 1 : 0;
    support_sum += support ? v : 0;
  }
  // Edges only tear (a restored yarn starts a new projection), so their count tells a change.
  return (intact << 40) ^ (supports << 20) ^ support_sum;
}

void LengthConstraintProjection::startFromLastCorrection(std::vector<Eigen::Vector3d>& position,
                                                         const EdgeSet& edges) {
  // The constraint forces change little from one step to the next while the pieces stay the
  // same: the free vertices start where the last step's constraint impulses (rescaled by dt^2)
  // would put them from the prediction. The fixed point is the prediction's; only the Newton
  // steps' start moves, by the change of those impulses over a step rather than by the
  // impulses themselves.
  if (last_correction_.size() != position.size() ||
      piecesSignature(edges) != correction_signature_) {
    return;
  }
  const double scale = time_step2_ / last_time_step2_;
  for (std::size_t v = 0; v < position.size(); ++v) {
    if (inverse_mass_[v] > 0.0) position[v] += scale * last_correction_[v];
  }
}

void LengthConstraintProjection::keepCorrection(const std::vector<Eigen::Vector3d>& position,
                                                const EdgeSet& edges, bool keep) {
  if (!keep) {
    last_correction_.clear();
    return;
  }
  last_correction_.resize(position.size());
  for (std::size_t v = 0; v < position.size(); ++v) {
    last_correction_[v] = position[v] - predicted_[v];
  }
  correction_signature_ = piecesSignature(edges);
}

void LengthConstraintProjection::updateHeldVertices(const EdgeSet& edges) {
  // Regroup only when the intact edges or the supports differ from the last time.
  const std::size_t n = inverse_mass_.size();
  const std::uint64_t signature = piecesSignature(edges);
  if (held_vertex_.size() == n && signature == held_signature_) return;
  held_signature_ = signature;
  pieces_.build(edges, n);
  held_vertex_.assign(n, 0);
  for (std::size_t v = 0; v < n; ++v) {
    if (inverse_mass_[v] == 0.0) held_vertex_[pieces_.root(static_cast<std::uint32_t>(v))] = 1;
  }
  for (std::size_t v = 0; v < n; ++v) {
    held_vertex_[v] = held_vertex_[pieces_.root(static_cast<std::uint32_t>(v))];
  }
}

double LengthConstraintProjection::forceMismatch(const std::vector<Eigen::Vector3d>& position,
                                                 const EdgeSet& edges, const ContactSet* contacts) {
  // dx_v = (x''_v - x~_v) - w_v sum_e m_e u_e: how far each vertex is from where the final
  // constraint forces, acting along the directions its corrections take (the final edge
  // directions, or the start ones for a vertex slow sideways), would have put it. Counted only
  // where the vertex's sideways stiffness is one the fast iterations treat unstably:
  // (omega dt)^2 > 1, a light vertex on a taut edge.
  computeSidewaysStiffness(edges);
  for (std::size_t v = 0; v < position.size(); ++v) {
    vertex_sum_[v] = position[v] - predicted_[v];
    vertex_scale_[v] = 0.0;
  }
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!candidate_[e]) continue;
    const std::uint32_t a = edges.vertex_a[e];
    const std::uint32_t b = edges.vertex_b[e];
    vertex_sum_[a] -= (inverse_mass_[a] * multiplier_[e]) * correctionDirection(e, false);
    vertex_sum_[b] += (inverse_mass_[b] * multiplier_[e]) * correctionDirection(e, true);
    vertex_scale_[a] = std::max(vertex_scale_[a], limit_[e]);
    vertex_scale_[b] = std::max(vertex_scale_[b], limit_[e]);
  }
  // The obstacles' impulses move the vertices too (on a frictionless face, along its normal).
  if (contacts != nullptr) contacts->addImpulses(inverse_mass_, -1.0, vertex_sum_);
  if (on_faces_) resting_.dropFaceNormals(vertex_sum_);
  double mismatch = 0.0;
  for (std::size_t v = 0; v < position.size(); ++v) {
    if (sideways_stiffness_[v] > 1.0 && vertex_scale_[v] > 0.0) {
      mismatch = std::max(mismatch, vertex_sum_[v].norm() / vertex_scale_[v]);
    }
  }
  return mismatch;
}

double LengthConstraintProjection::evaluate(const std::vector<Eigen::Vector3d>& position,
                                            const EdgeSet& edges) {
  double max_violation = 0.0;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const std::uint32_t a = edges.vertex_a[e];
    const std::uint32_t b = edges.vertex_b[e];
    const bool movable = inverse_mass_[a] + inverse_mass_[b] > 0.0;
    candidate_[e] = edges.intact(e) && movable ? 1 : 0;
    if (!candidate_[e]) {
      active_[e] = 0;
      continue;
    }
    const Eigen::Vector3d d = position[b] - position[a];
    const double length = d.norm();
    direction_[e] = length > 0.0 ? Eigen::Vector3d(d / length) : Eigen::Vector3d::Zero();
    stretch_state_.settle(edges, e, multiplier_[e]);
    limit_[e] = stretch_state_.limit(e, multiplier_[e]);
    residual_[e] = length - limit_[e];
    const bool holding = multiplier_[e] > 0.0;
    active_[e] = (residual_[e] > 0.0 || holding) ? 1 : 0;
    const double violation = holding ? std::abs(residual_[e]) : std::max(residual_[e], 0.0);
    max_violation = std::max(max_violation, violation / limit_[e]);
  }
  return max_violation;
}

void LengthConstraintProjection::multiplyGram(const EdgeSet& edges,
                                              const std::vector<double>& multiplier,
                                              std::vector<double>& product,
                                              const std::vector<double>* row_multiplier) {
  for (Eigen::Vector3d& p : vertex_sum_) p.setZero();
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!candidate_[e] || multiplier[e] == 0.0) continue;
    vertex_sum_[edges.vertex_a[e]] -= multiplier[e] * direction_[e];
    vertex_sum_[edges.vertex_b[e]] += multiplier[e] * direction_[e];
  }
  if (fast_contacts_ != nullptr) {
    fast_rows_.addGradients(*row_multiplier, vertex_sum_);
    fast_rows_.multiply(inverse_mass_, vertex_sum_, row_product_);
  }
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!candidate_[e]) continue;
    const std::uint32_t a = edges.vertex_a[e];
    const std::uint32_t b = edges.vertex_b[e];
    product[e] =
        direction_[e].dot(inverse_mass_[b] * vertex_sum_[b] - inverse_mass_[a] * vertex_sum_[a]);
  }
}

void LengthConstraintProjection::solveComplementarity(const EdgeSet& edges, EdgeGramSolver& gram,
                                                      const GramSystem& system) {
  // Block principal pivoting: guess the set of taut edges, solve them as equalities, move the
  // edges whose force came out compressive out of the set and the slack edges that the solution
  // would stretch into it, and switch taut edges between compliant and held at their breaking
  // length as their force crosses the one that reaches it, until nothing moves. The frontier takes
  // in runs of slack edges that a pull would straighten at once instead of one per pass.
  frontier_.reset(edges.size());
  for (int pass = 0; pass < kMaxPivotingPasses; ++pass) {
    for (std::size_t e = 0; e < edges.size(); ++e) step_[e] = active_[e] ? target_[e] : 0.0;
    if (fast_contacts_ != nullptr) {
      fast_rows_.solve(edges, gram, system, inverse_mass_, step_);
    } else {
      gram.solve(edges, system, step_);
    }
    multiplyGram(edges, step_, product_, &fast_rows_.passMultiplier());
    frontier_.beginPass(candidate_, active_, step_);
    bool changed = false;
    for (std::size_t e = 0; e < edges.size(); ++e) {
      if (!candidate_[e]) continue;
      stretch_[e] = target_[e] - product_[e];
      if (active_[e]) {
        if (step_[e] < 0.0 && frontier_.mayLeave(e)) {
          active_[e] = 0;
          frontier_.left(e);
          target_[e] += stretch_state_.release(edges, e);
          changed = true;
        } else if (step_[e] > 0.0 && stretch_state_.wouldSwitch(e, step_[e])) {
          target_[e] += stretch_state_.settle(edges, e, step_[e]);
          changed = true;
        }
      } else if (stretch_[e] > slack_tolerance_ * limit_[e]) {
        // A slack edge joins only when the solution would stretch it past the tolerance, so
        // that edges right at their limit do not flip in and out on round-off.
        active_[e] = 1;
        frontier_.joined(e);
        changed = true;
      }
    }
    if (fast_contacts_ != nullptr && fast_rows_.pivot(row_product_, slack_tolerance_)) {
      changed = true;
    }
    if (!changed) return;
    frontier_.grow(edges, gram.incidence(), candidate_, stretch_, active_);
  }
}

ProjectionResult LengthConstraintProjection::projectFast(
    std::vector<Eigen::Vector3d>& position, const EdgeSet& edges,
    const SimulationParameters& parameters, EdgeGramSolver& gram, ContactSet* contacts,
    const std::vector<Eigen::Vector3d>* step_start) {
  const GramSystem system = beginFastProjection(position, edges, parameters, contacts);
  FastLoop loop;
  // The Newton steps do not keep vertices on faces (on_faces_): not for those.
  loop.newton_first = contacts == nullptr && !on_faces_ && newtonFirst(edges.size());
  if (loop.newton_first) resumeFlow(edges);
  if (loop.newton_first && fast_contacts_ == nullptr) startFromLastCorrection(position, edges);
  ProjectionResult result;
  measureIterate(position, edges, contacts, result);
  resetCorrectionDirections(edges.size());
  // Start directions (SHAKE) only without contacts: the contact rows' Newton steps solve the
  // symmetric system exactly, with final directions.
  if (step_start != nullptr && contacts == nullptr) chooseCorrectionDirections(*step_start, edges);
  warmStartActiveSet(edges);
  newton_.beginProjection(parameters.time_step, slack_tolerance_);
  for (;;) {
    checkConvergence(position, edges, parameters, contacts, loop, result);
    if (result.converged || result.iterations >= parameters.max_projection_iterations) break;
    // With contacts, the fast iterations first bring the edges near their limits (a pulled end
    // may be predicted metres away, too far for Newton steps to start from); then Newton steps
    // settle the edges and the contacts together.
    loop.use_newton = loop.use_newton || contacts != nullptr || loop.newton_first;
    // Contact rows in the fast iterations: when these do not settle, the caller takes the full
    // solve with Newton steps and contact rows instead.
    if ((fast_contacts_ != nullptr || on_faces_) &&
        (loop.use_newton || result.iterations >= kFastIterations)) {
      break;
    }
    if (!loop.use_newton && result.iterations >= kFastIterations) {
      loop.fast_iterations_stalled = true;
    }
    // Not converged with start directions (a step that tears or jerks the piece far from where
    // it started): finish on final directions, which always converge. Their Newton systems are
    // symmetric, and pivoting on them settles a changing taut set in fewer solves: so also once
    // a Newton step past the first few still changed its taut set.
    const bool still_pivoting =
        newton_.steps() >= kStartDirectionNewtonSteps && newton_.stoppedEarly();
    if (any_start_direction_ &&
        (still_pivoting || result.iterations == kStartDirectionIterations)) {
      resetCorrectionDirections(edges.size());
    }
    if (loop.use_newton || result.iterations >= kFastIterations) {
      // The fast iterations stall (a light yarn swung hard by a heavy end): finish with Newton
      // steps that include the geometric stiffness.
      newtonIteration(position, edges, gram, contacts);
    } else {
      fastIteration(position, edges, gram, system);
    }
    ++result.iterations;
    measureIterate(position, edges, contacts, result);
  }
  endFastProjection(edges, loop, result.converged);
  keepCorrection(position, edges,
                 result.converged && contacts == nullptr && fast_contacts_ == nullptr);
  return result;
}

GramSystem LengthConstraintProjection::beginFastProjection(std::vector<Eigen::Vector3d>& position,
                                                           const EdgeSet& edges,
                                                           const SimulationParameters& parameters,
                                                           const ContactSet* contacts) {
  GramSystem system;
  system.direction = &direction_;
  system.vertex_weight = &inverse_mass_;
  system.active = &active_;
  system.diagonal_shift = &stretch_state_.shift();
  slack_tolerance_ = 0.1 * parameters.constraint_tolerance;
  newton_taut_.resize(edges.size());
  vertex_sum_.resize(position.size());
  vertex_scale_.resize(position.size());
  sideways_stiffness_.resize(position.size());
  predicted_ = position;
  if (contacts != nullptr) {
    // Newton steps from where the free vertices started (clear of the obstacles, the edges
    // near their limits), not from the prediction, which a pulled end may put metres away.
    const std::vector<Eigen::Vector3d>& start = contacts->start();
    for (std::size_t v = 0; v < position.size(); ++v) {
      if (inverse_mass_[v] > 0.0) position[v] = start[v];
    }
    if (last_multiplier_.size() == multiplier_.size()) multiplier_ = last_multiplier_;
  }
  return system;
}

void LengthConstraintProjection::measureIterate(const std::vector<Eigen::Vector3d>& position,
                                                const EdgeSet& edges, ContactSet* contacts,
                                                ProjectionResult& result) {
  result.max_violation = evaluate(position, edges);
  if (contacts != nullptr) {
    contacts->linearize(position);
    result.max_penetration = contacts->maxPenetration();
  }
  if (fast_contacts_ != nullptr) linearizeFastRows(position, result);
}

void LengthConstraintProjection::resetCorrectionDirections(std::size_t num_edges) {
  start_at_a_.assign(num_edges, 0);
  start_at_b_.assign(num_edges, 0);
  any_start_direction_ = false;
}

void LengthConstraintProjection::resumeFlow(const EdgeSet& edges) {
  if (was_flowing_.size() != edges.size()) return;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (was_flowing_[e] && multiplier_[e] > 0.0) stretch_state_.resumeFlow(edges, e);
  }
}

void LengthConstraintProjection::warmStartActiveSet(const EdgeSet& edges) {
  // The edges that were taut at the end of the last step most likely still are.
  was_taut_.resize(edges.size(), 0);
  for (std::size_t e = 0; e < edges.size(); ++e) active_[e] |= candidate_[e] & was_taut_[e];
}

void LengthConstraintProjection::checkConvergence(const std::vector<Eigen::Vector3d>& position,
                                                  const EdgeSet& edges,
                                                  const SimulationParameters& parameters,
                                                  const ContactSet* contacts, FastLoop& loop,
                                                  ProjectionResult& result) {
  // With contacts the iterations start at the step's start, which is not the answer.
  const bool within = result.max_violation <= parameters.constraint_tolerance &&
                      result.max_penetration <= parameters.constraint_tolerance &&
                      (contacts == nullptr ||
                       (result.iterations > 0 && newton_.impulseChange() <= kImpulseTolerance &&
                        last_move_ <= parameters.constraint_tolerance)) &&
                      (!loop.newton_first || result.iterations > 0);
  // A Newton step that stopped pivoting early solved its linearization's complementarity
  // problem only approximately: the projection ends on one that solved it exactly (the next
  // pivots fully).
  result.converged = within && !newton_.stoppedEarly();
  if (within && newton_.stoppedEarly()) newton_.pivotFully();
  if (!result.converged) return;
  // Held to their limits, but do the constraint forces act along the final edge directions?
  // Where they act along the directions the iterations started from, a light vertex on a
  // taut span is flung across the line (the span's transverse stiffness treated explicitly,
  // unstable for dt^2 T / (m l) > 1): then finish with Newton steps, whose geometric
  // stiffness makes that part implicit too.
  result.force_mismatch =
      forceMismatch(position, edges, fast_contacts_ != nullptr ? fast_contacts_ : contacts);
  result.converged = result.force_mismatch <= parameters.constraint_tolerance;
  // Newton steps with contacts that have settled but for the force directions have stalled
  // at the round-off of their solve (a wrap at (omega dt)^2 ~ 1e7): refine their solves.
  if (!result.converged && contacts != nullptr && result.iterations > 0) newton_.refineSolves();
  loop.mismatch_needed_newton =
      loop.mismatch_needed_newton || (!result.converged && !loop.use_newton);
  loop.use_newton = loop.use_newton || !result.converged;
}

void LengthConstraintProjection::newtonIteration(std::vector<Eigen::Vector3d>& position,
                                                 const EdgeSet& edges, EdgeGramSolver& gram,
                                                 ContactSet* contacts) {
  for (std::size_t e = 0; e < edges.size(); ++e) {
    // With contacts every edge starts taut (pivoting releases the slack ones): guessing a
    // pulled yarn slack lets the first pass fling it through the obstacles. An edge the last
    // Newton step released with push p comes back only past the move that push wanted, the
    // primal-dual active-set rule m + C / (w_a + w_b) > 0 with m = -p: it was held at its
    // linearized length, which a turn lengthens (C > 0 at second order), and by the plain C > 0
    // it came back and left again in every step.
    newton_taut_[e] =
        candidate_[e] &&
        (multiplier_[e] > 0.0 || residual_[e] > newton_.releasedMove(e) || contacts != nullptr);
  }
  iterate_ = position;
  newton_.apply(predicted_, inverse_mass_, edges, gram.incidence(), stretch_state_, candidate_,
                newton_taut_, position, multiplier_, contacts,
                any_start_direction_
                    ? StartDirections{&start_direction_, &start_at_a_, &start_at_b_}
                    : StartDirections{});
  // With contacts, a Newton step is accepted only once it hardly moves anything: the
  // violation alone does not show a stationarity error, which a wrap can let grow.
  last_move_ = 0.0;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!candidate_[e]) continue;
    for (const std::uint32_t v : {edges.vertex_a[e], edges.vertex_b[e]}) {
      last_move_ = std::max(last_move_, (position[v] - iterate_[v]).norm() / limit_[e]);
    }
  }
}

void LengthConstraintProjection::fastIteration(std::vector<Eigen::Vector3d>& position,
                                               const EdgeSet& edges, EdgeGramSolver& gram,
                                               const GramSystem& system) {
  // Linearized at the current iterate x_k (directions J, Gram matrix K = J W J^T), moving the
  // vertices by -W J^T (m - m_k) gives C(x_k) - K (m - m_k) - (c/dt^2) m <= 0 for every edge,
  // with m >= 0 the total multipliers and each product zero: a linear complementarity
  // problem in m, solved exactly. A taut edge may thus become slack (its pull is taken back)
  // but never pushes.
  multiplyGram(edges, multiplier_, product_, &fast_rows_.multiplier());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    target_[e] = residual_[e] + stretch_state_.shift()[e] * multiplier_[e] + product_[e];
  }
  if (fast_contacts_ != nullptr) fast_rows_.setTargets(row_product_);
  solveComplementarity(edges, gram, system);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!candidate_[e]) continue;
    const double total = std::max(step_[e], 0.0);
    const double change = total - multiplier_[e];
    multiplier_[e] = total;
    if (change == 0.0) continue;
    const std::uint32_t a = edges.vertex_a[e];
    const std::uint32_t b = edges.vertex_b[e];
    position[a] += (inverse_mass_[a] * change) * correctionDirection(e, false);
    position[b] -= (inverse_mass_[b] * change) * correctionDirection(e, true);
  }
  if (fast_contacts_ != nullptr) {
    fast_rows_.accept(inverse_mass_, position);
    fast_rows_.store(*fast_contacts_);
  }
  if (on_faces_) resting_.keepOnFaces(position);
}

void LengthConstraintProjection::endFastProjection(const EdgeSet& edges, const FastLoop& loop,
                                                   bool converged) {
  was_flowing_.resize(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    was_taut_[e] = multiplier_[e] > 0.0 ? 1 : 0;
    was_flowing_[e] = was_taut_[e] && stretch_state_.flowing(e) ? 1 : 0;
  }
  last_multiplier_ = multiplier_;
  if (!converged) computeSidewaysStiffness(edges);  // else forceMismatch's is current
  last_stiffness_.swap(sideways_stiffness_);
  last_time_step2_ = time_step2_;
  newton_first_next_ =
      loop.newton_first || loop.fast_iterations_stalled || loop.mismatch_needed_newton;
}

ProjectionResult LengthConstraintProjection::projectGaussSeidel(
    std::vector<Eigen::Vector3d>& position, const EdgeSet& edges,
    const SimulationParameters& parameters) {
  ProjectionResult result;
  for (;;) {
    result.max_violation = evaluate(position, edges);
    result.converged = result.max_violation <= parameters.constraint_tolerance;
    if (result.converged || result.iterations >= parameters.max_projection_iterations) break;
    for (std::size_t e = 0; e < edges.size(); ++e) {
      if (!active_[e]) continue;
      const std::uint32_t a = edges.vertex_a[e];
      const std::uint32_t b = edges.vertex_b[e];
      const Eigen::Vector3d d = position[b] - position[a];
      const double length = d.norm();
      stretch_state_.settle(edges, e, multiplier_[e]);
      const double residual = length - stretch_state_.limit(e, multiplier_[e]);
      const double denominator = inverse_mass_[a] + inverse_mass_[b] + stretch_state_.shift()[e];
      const double dl = std::max(residual / denominator, -multiplier_[e]);
      if (dl == 0.0 || !(length > 0.0)) continue;
      multiplier_[e] += dl;
      const Eigen::Vector3d n = d / length;
      position[a] += (inverse_mass_[a] * dl) * n;
      position[b] -= (inverse_mass_[b] * dl) * n;
    }
    ++result.iterations;
  }
  return result;
}

}  // namespace yarn_tearing
