#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/contact/contact_set.hpp"
#include "yarn_tearing/core/contact/fast_contact_rows.hpp"
#include "yarn_tearing/core/contact/resting_contacts.hpp"
#include "yarn_tearing/core/model/connected_pieces.hpp"
#include "yarn_tearing/core/model/edge_set.hpp"
#include "yarn_tearing/core/model/vertex_set.hpp"
#include "yarn_tearing/core/projection/edge_gram_solver.hpp"
#include "yarn_tearing/core/projection/edge_stretch_limits.hpp"
#include "yarn_tearing/core/projection/edge_stretch_state.hpp"
#include "yarn_tearing/core/projection/stiff_newton_step.hpp"
#include "yarn_tearing/core/projection/taut_frontier.hpp"
#include "yarn_tearing/core/simulation/simulation_parameters.hpp"

namespace yarn_tearing {

/// Outcome of one projection.
struct ProjectionResult {
  int iterations = 0;          ///< iterations (direction updates) or Gauss–Seidel sweeps
  double max_violation = 0.0;  ///< max (length - limit) / limit over intact edges [-]
  /// Largest penetration of a contact point into an obstacle, relative to its edge length [-].
  double max_penetration = 0.0;
  /// max over free vertices of |(x'' - x~) - W J(x'')^T m| / l [-]: how far the constraint
  /// forces, taken along the final edge directions, are from explaining each vertex's
  /// correction (l its longest incident limit), over the vertices whose sideways stiffness the
  /// fast iterations treat unstably ((omega dt)^2 = w sum_e m_e / l_e > 1). Fast projection only.
  double force_mismatch = 0.0;
  bool converged = false;  ///< max_violation, max_penetration, force_mismatch <= tolerance
  int factorizations = 0;  ///< Newton systems factorized [-]
  /// Symbolic analyses of their patterns (StiffNewtonStep::analyses()) [-].
  int analyses = 0;
};

/// Stage 3: limits every intact edge, stretch only, to
///   |x_a - x_b| <= L + min(c T, s_max),
/// with L the (plastic) rest length, c the compliance of the edge's constraint [m/N] (its elastic
/// compliance L0 / (E A) less the soft spring's share, EdgeStretchLimits), T the
/// force the constraint itself exerts (its multiplier / dt^2) and s_max the stretch [m] at which
/// the edge reaches its breaking length (EdgeStretchLimits). The strain limit is thus the
/// elastic strain of the edge's current stress (paper §3.3), solved in the same system
/// rather than lagged by a step: the lagged update oscillates and grows once the yarn's own
/// elastic vibration is resolved by the time step (omega dt < 1, e.g. a heavy weight), while this
/// one is stable at any dt and mass ratio and reduces to the hard constraint when E A is large.
/// At the breaking length the constraint turns hard (linearized per iteration): an overload
/// holds the edge there, at any force, until the tearing stage cuts it.
///
/// The projection is mass-weighted, as the fast projection of Goldenthal et al. (2007): the
/// vertices move by -W J^T (change of the multipliers), W the inverse masses. Each iteration
/// linearizes at the current positions and solves the resulting linear complementarity problem
/// in the total multipliers exactly (taut edges pull, slack ones carry nothing, none pushes) by
/// block principal pivoting over a banded (chains) or sparse solve; a TautFrontier takes in a
/// whole run of slack edges that a pull straightens at once, where plain pivoting would take one
/// edge per pass. Edges whose vertices are all pinned or kinematic cannot be corrected and are
/// not counted in the violation; their force is that of a stiff spring of the same compliance
/// (and stop) at the length their holders give them, so they carry tension and can tear.
///
/// Contacts with obstacles (ContactSet: non-penetration of vertices and segment points, Coulomb
/// friction) are more rows of the same complementarity problem. When a step has any, the
/// projection runs the Newton steps (StiffNewtonStep) from its first iteration, which carry the
/// contact rows beside the edges' and settle both by the same pivoting.
class LengthConstraintProjection {
 public:
  /// Newton steps solve their whole systems (StiffNewtonStep::forceFullSystems).
  void forceFullNewtonSystems(bool force) { newton_.forceFullSystems(force); }
  /// Newton steps factorize every system (StiffNewtonStep::forceFreshFactorizations).
  void forceFreshFactorizations(bool force) { newton_.forceFreshFactorizations(force); }
  /// Threads the Newton steps' factorizations may use [-] (StiffNewtonStep::setThreads).
  void setThreads(int threads) { newton_.setThreads(threads); }
  /// Projects `position` in place. `limits` gives each edge's compliance c [m/N] and largest
  /// stretch [m]; masses and supports come from `vertices`. With `step_start` [m], the
  /// positions at the start of the step, a vertex that is slow sideways ((omega dt)^2 <=
  /// kStartDirectionStiffness at the end of the last projection) in a piece that a support
  /// holds feels its edges' forces along their directions at the step's start, as in SHAKE
  /// (symplectic: a swinging weight keeps its energy). Every other vertex, and all without
  /// `step_start`, feels them along the final directions (backward Euler: stable however stiff
  /// a light vertex's sideways mode, conserves a free piece's momentum, but damps a swing at
  /// first order in dt).
  ProjectionResult project(std::vector<Eigen::Vector3d>& position, const VertexSet& vertices,
                           const EdgeSet& edges, const EdgeStretchLimits& limits,
                           const SimulationParameters& parameters, EdgeGramSolver& gram,
                           ContactSet* contacts = nullptr,
                           const std::vector<Eigen::Vector3d>* step_start = nullptr);

  /// Force each edge's constraint exerted in the last projection [N] (0 where inactive).
  double constraintForce(std::size_t e) const { return multiplier_[e] / time_step2_; }
  /// The next projection starts its Newton steps from the prediction itself, not moved by this
  /// one's correction: for substeps of a recoil or of a retried step, whose constraint forces
  /// change within a substep by as much as they are (a 16 x 16 trouser tear's recoil took 40-82
  /// Newton steps with the start, 23-29 without).
  void forgetCorrection() { last_correction_.clear(); }

 private:
  /// The fast path for contacts: the vertices that stuck on a face in the last step held where
  /// they stuck (RestingContacts), the few other contact points as rows of the fast iterations
  /// (FastContactRows). True when the fast iterations converge and every contact's
  /// complementarity holds (the impulses are then stored in `contacts`); false, with everything
  /// restored for the full solve (Newton steps with contact rows), otherwise.
  bool projectContactsFast(std::vector<Eigen::Vector3d>& position, const VertexSet& vertices,
                           const EdgeSet& edges, const EdgeStretchLimits& limits,
                           const SimulationParameters& parameters, EdgeGramSolver& gram,
                           ContactSet& contacts, ProjectionResult& result);
  /// Sets the multiplier of each intact edge between two pinned or kinematic vertices from its
  /// length (EdgeStretchState::multiplierAtLength).
  void holdEdgesBetweenSupports(const std::vector<Eigen::Vector3d>& position, const EdgeSet& edges);
  /// Chooses, per edge end, the direction its corrections take: the start direction where the
  /// vertex is slow sideways and the edge has not turned by much since the step's start.
  void chooseCorrectionDirections(const std::vector<Eigen::Vector3d>& step_start,
                                  const EdgeSet& edges);
  /// Direction [-] along which edge e moves its end vertex v (a or b) in this projection.
  const Eigen::Vector3d& correctionDirection(std::size_t e, bool end_b) const {
    return (end_b ? start_at_b_[e] : start_at_a_[e]) ? start_direction_[e] : direction_[e];
  }
  /// True when this projection starts with Newton steps: newton_first_next_ and some vertex
  /// stiffer sideways at the end of the last projection, rescaled to this step's dt^2, than the
  /// fast iterations treat stably ((omega dt)^2 > 1). Then warm-starts the multipliers from the
  /// last projection's (rescaled by dt^2).
  bool newtonFirst(std::size_t num_edges);
  /// A number that changes when an edge tears or a vertex becomes or stops being a support.
  std::uint64_t piecesSignature(const EdgeSet& edges) const;
  /// Moves the free vertices from the prediction by the last projection's correction
  /// (last_correction_), where the pieces are the same as then.
  void startFromLastCorrection(std::vector<Eigen::Vector3d>& position, const EdgeSet& edges);
  /// Keeps this projection's correction (position - predicted_) for the next one when `keep`
  /// (a converged projection without contacts, whose impulses the next may not have), else none.
  void keepCorrection(const std::vector<Eigen::Vector3d>& position, const EdgeSet& edges,
                      bool keep);
  /// Sets held_vertex_ (regrouping the pieces only when edges or supports changed).
  void updateHeldVertices(const EdgeSet& edges);
  /// (omega dt)^2 of every vertex's sideways mode [-] from the current multipliers.
  void computeSidewaysStiffness(const EdgeSet& edges);
  /// ProjectionResult::force_mismatch of `position` (directions from the last evaluate).
  double forceMismatch(const std::vector<Eigen::Vector3d>& position, const EdgeSet& edges,
                       const ContactSet* contacts);
  /// Fills directions, residuals and the active set; returns the max relative violation.
  double evaluate(const std::vector<Eigen::Vector3d>& position, const EdgeSet& edges);
  /// The fast projection: fast iterations (exact complementarity of each linearization on the
  /// Gram matrix), and Newton steps (StiffNewtonStep) where those stall, with contacts, or where
  /// the last projection needed them (newtonFirst()).
  ProjectionResult projectFast(std::vector<Eigen::Vector3d>& position, const EdgeSet& edges,
                               const SimulationParameters& parameters, EdgeGramSolver& gram,
                               ContactSet* contacts,
                               const std::vector<Eigen::Vector3d>* step_start);
  /// How one projectFast() call iterates.
  struct FastLoop {
    bool newton_first = false;  ///< it started with Newton steps (newtonFirst())
    bool use_newton = false;    ///< Newton steps from here on
    /// kFastIterations fast iterations did not converge.
    bool fast_iterations_stalled = false;
    /// The fast iterations held the lengths but not the forces' directions (force_mismatch).
    bool mismatch_needed_newton = false;
  };
  /// Sizes the work arrays, keeps the prediction (predicted_) and, with contacts, starts the
  /// free vertices at the step's start from the last multipliers; returns the Gram system of the
  /// fast iterations.
  GramSystem beginFastProjection(std::vector<Eigen::Vector3d>& position, const EdgeSet& edges,
                                 const SimulationParameters& parameters,
                                 const ContactSet* contacts);
  /// Evaluates the edges (evaluate()) and linearizes the contacts at `position`: the violation
  /// and penetration of `result`.
  void measureIterate(const std::vector<Eigen::Vector3d>& position, const EdgeSet& edges,
                      ContactSet* contacts, ProjectionResult& result);
  /// Every edge end corrected along the final directions.
  void resetCorrectionDirections(std::size_t num_edges);
  /// Puts the edges that flowed at the end of the last projection back on their flow pieces
  /// (EdgeStretchState::resumeFlow), where their multipliers start from the last ones.
  void resumeFlow(const EdgeSet& edges);
  /// Adds the edges taut at the end of the last projection to the active set.
  void warmStartActiveSet(const EdgeSet& edges);
  /// Sets result.converged (violation, penetration, contacts settled, then force_mismatch) and
  /// switches `loop` to Newton steps where the forces' directions are not yet right.
  void checkConvergence(const std::vector<Eigen::Vector3d>& position, const EdgeSet& edges,
                        const SimulationParameters& parameters, const ContactSet* contacts,
                        FastLoop& loop, ProjectionResult& result);
  /// One Newton step (StiffNewtonStep) from the current taut edges; sets last_move_.
  void newtonIteration(std::vector<Eigen::Vector3d>& position, const EdgeSet& edges,
                       EdgeGramSolver& gram, ContactSet* contacts);
  /// One fast iteration: the linearization's complementarity problem solved exactly, the
  /// vertices moved by the change of the multipliers.
  void fastIteration(std::vector<Eigen::Vector3d>& position, const EdgeSet& edges,
                     EdgeGramSolver& gram, const GramSystem& system);
  /// Keeps what the next projection starts from: the taut edges, multipliers, sideways
  /// stiffness and whether it starts with Newton steps.
  void endFastProjection(const EdgeSet& edges, const FastLoop& loop, bool converged);
  /// product = K multiplier, K = J W J^T over the candidate edges (matrix-free, any graph); with
  /// fast contact rows, `row_multiplier` their multipliers, and row_product_ their products.
  void multiplyGram(const EdgeSet& edges, const std::vector<double>& multiplier,
                    std::vector<double>& product,
                    const std::vector<double>* row_multiplier = nullptr);
  /// Linearizes the contacts and the fast contact rows at `position`; sets the penetration.
  void linearizeFastRows(const std::vector<Eigen::Vector3d>& position, ProjectionResult& result);
  /// Solves the linear complementarity problem of one iteration: step_ = multipliers >= 0.
  void solveComplementarity(const EdgeSet& edges, EdgeGramSolver& gram, const GramSystem& system);
  ProjectionResult projectGaussSeidel(std::vector<Eigen::Vector3d>& position, const EdgeSet& edges,
                                      const SimulationParameters& parameters);

  double time_step2_ = 1.0;                 ///< dt^2 [s^2]
  std::vector<double> inverse_mass_;        ///< [1/kg]
  EdgeStretchState stretch_state_;          ///< compliant or held at the breaking length
  std::vector<Eigen::Vector3d> direction_;  ///< unit edge directions
  std::vector<double> residual_;            ///< length - limit [m]
  std::vector<double> limit_;               ///< B + S m (EdgeStretchState) [m]
  std::vector<double> multiplier_;          ///< accumulated multipliers T dt^2 [kg*m]
  /// The multipliers the last projection ended with (Newton steps with contacts start there).
  std::vector<double> last_multiplier_;
  std::vector<Eigen::Vector3d> iterate_;  ///< positions before the last Newton step [m]
  double last_move_ = 0.0;            ///< largest move of the last Newton step per edge length [-]
  std::vector<double> step_;          ///< candidate multipliers of a pivoting pass [kg*m]
  std::vector<std::uint8_t> active_;  ///< edges in the active set
  std::vector<std::uint8_t> candidate_;  ///< intact edges with a movable vertex
  std::vector<std::uint8_t> was_taut_;   ///< edges taut at the end of the last projection
  /// Edges flowing at the end of the last projection (EdgeStretchState::flowing).
  std::vector<std::uint8_t> was_flowing_;
  std::vector<double> target_;              ///< right-hand side of the complementarity problem
  std::vector<double> product_;             ///< K times a multiplier vector [m]
  std::vector<double> stretch_;             ///< a pass's stretch past the limit per edge [m]
  TautFrontier frontier_;                   ///< takes in runs of slack edges at once
  std::vector<Eigen::Vector3d> predicted_;  ///< positions before the projection [m]
  /// Final minus predicted position of each vertex in the last contact-free projection [m].
  std::vector<Eigen::Vector3d> last_correction_;
  std::uint64_t correction_signature_ = 0;  ///< piecesSignature() when it was kept
  StiffNewtonStep newton_;                  ///< fallback when the fast iterations stall
  RestingContacts resting_;                 ///< the resting-contact fast path
  FastContactRows fast_rows_;               ///< few contact points in the fast iterations
  /// The contacts of fast_rows_ while projectContactsFast() runs the fast iterations, else null.
  ContactSet* fast_contacts_ = nullptr;
  std::vector<double> row_product_;  ///< K times the multipliers, per fast contact row [m]
  /// While projectContactsFast() runs the fast iterations with vertices kept on frictionless
  /// faces (RestingContacts): their corrections lose the normal component, no Newton steps.
  bool on_faces_ = false;
  /// What projectContactsFast() restores when its guess fails.
  struct RestingFallback {
    std::vector<Eigen::Vector3d> position;  ///< the prediction [m]
    std::vector<double> last_multiplier;    ///< see last_multiplier_ [kg m]
    std::vector<std::uint8_t> was_taut;     ///< see was_taut_
    std::vector<std::uint8_t> was_flowing;  ///< see was_flowing_
    std::vector<double> last_stiffness;     ///< see last_stiffness_ [-]
    double last_time_step2 = 1.0;           ///< see last_time_step2_ [s^2]
    bool newton_first_next = false;         ///< see newton_first_next_
  };
  RestingFallback resting_fallback_;
  std::vector<std::uint8_t> newton_taut_;    ///< edges the Newton step takes as equalities
  static constexpr int kFastIterations = 6;  ///< fast iterations before Newton takes over
  std::vector<Eigen::Vector3d> vertex_sum_;  ///< per-vertex sum of multiplier * direction
  std::vector<double> vertex_scale_;         ///< longest incident limit per vertex [m]
  std::vector<double> sideways_stiffness_;   ///< (omega dt)^2 of each vertex's sideways mode [-]
  /// (omega dt)^2 of each vertex's sideways mode at the last projection's end [-] (infinite
  /// before the first: every vertex starts on final directions), and that projection's dt^2.
  std::vector<double> last_stiffness_;
  double last_time_step2_ = 1.0;                  ///< [s^2]
  std::vector<Eigen::Vector3d> start_direction_;  ///< unit edge directions at the step's start
  ConnectedPieces pieces_;                        ///< the pieces the intact edges join
  std::vector<std::uint8_t> held_vertex_;         ///< the vertex's piece has a support
  std::uint64_t held_signature_ = 0;              ///< intact edges and supports held_vertex_ is for
  std::vector<std::uint8_t> start_at_a_;  ///< edge moves its vertex a along start_direction_
  std::vector<std::uint8_t> start_at_b_;  ///< edge moves its vertex b along start_direction_
  /// Some edge end takes its start direction in this projection (else the Newton steps need no
  /// refinement on an unsymmetric system).
  bool any_start_direction_ = false;
  /// Largest (omega dt)^2 [-] of a vertex corrected along start directions: the explicit
  /// treatment of its sideways mode is stable below 4 (Stormer-Verlet), kept well inside.
  static constexpr double kStartDirectionStiffness = 0.25;
  /// Iterations after which a projection not yet converged drops the start directions.
  static constexpr int kStartDirectionIterations = 20;
  /// Newton steps after which a projection whose last Newton step still changed its taut set
  /// (a quick step that stopped early) drops the start directions: pivoting on the unsymmetric
  /// systems they make takes many solves to settle a taut set that a tear or a whip changes.
  static constexpr int kStartDirectionNewtonSteps = 3;
  /// Smallest cosine [-] between an edge's start and predicted directions for the start one
  /// to be used (an edge that turned further, e.g. a whipping slack end, is corrected along
  /// its current direction).
  static constexpr double kStartDirectionCosine = 0.99;
  /// Relative change of the contact impulses in the last Newton step below which they have
  /// settled [-] (StiffNewtonStep::impulseChange()). Looser than the constraint tolerance: a
  /// stuck wrap's friction rows are nearly dependent (the points' moves are well determined,
  /// the share of the impulses between them only through the yarn's compliance), and their
  /// round-off alone moves the impulses by 1e-5.
  static constexpr double kImpulseTolerance = 1e-4;
  double slack_tolerance_ = 0.0;  ///< relative stretch a slack edge may show before it joins
  static constexpr int kMaxPivotingPasses = 30;  ///< active-set passes per iteration
  /// The last projection's fast iterations stalled (or it started with Newton steps): while the
  /// piece stays stiff sideways, the next one starts with Newton steps from the warm multipliers
  /// rather than let the fast iterations fling the light vertices first (a fabric drawn taut:
  /// moves of 100 edge lengths, then 20 Newton steps to come back). See newtonFirst().
  bool newton_first_next_ = false;
};

}  // namespace yarn_tearing
