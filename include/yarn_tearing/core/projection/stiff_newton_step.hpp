#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <array>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/contact/contact_set.hpp"
#include "yarn_tearing/core/linalg/banded_ldlt.hpp"
#include "yarn_tearing/core/linalg/pattern_cached_ldlt.hpp"
#include "yarn_tearing/core/model/edge_incidence.hpp"
#include "yarn_tearing/core/model/edge_set.hpp"
#include "yarn_tearing/core/projection/edge_stretch_state.hpp"
#include "yarn_tearing/core/projection/taut_frontier.hpp"
#include "yarn_tearing/core/projection/vertex_condensation.hpp"

namespace yarn_tearing {

/// Where a projection corrects a vertex along the edge direction at the step's start rather
/// than along the final one (LengthConstraintProjection): per edge, its start direction and a
/// flag for each end. Such an end feels its edge's force along the fixed start direction (no
/// geometric stiffness), as in SHAKE.
struct StartDirections {
  const std::vector<Eigen::Vector3d>* direction = nullptr;  ///< unit start direction per edge
  const std::vector<std::uint8_t>* at_a = nullptr;  ///< vertex a moves along the start direction
  const std::vector<std::uint8_t>* at_b = nullptr;  ///< vertex b moves along the start direction
};

/// One Newton step of the exact implicit projection, with geometric stiffness:
///   M (x - x~) + J(x)^T m = 0,    C_e(x) - s_e m_e = 0 for the taut edges,  m >= 0,
/// C_e = |x_b - x_a| - B_e (B_e the base length: the rest length, or the breaking length where
/// the stretch is at its largest), s_e = c_e / dt^2 the compliance term [1/kg], m the multipliers
/// [kg*m]. Linearized, (M + sum_e m_e Hess C_e) dx + J^T m' = -M (x - x~) and J dx - s m' = -C,
/// a quasi-definite system solved by sparse LDL^T. The geometric stiffness keeps a light vertex
/// between two taut edges from being flung across the line (what stalls the fast projection
/// when a heavy end swings a light yarn), and the fixed point conserves momentum exactly.
/// The taut set is settled by block principal pivoting: edges whose multiplier comes out
/// negative are released, slack edges the step would stretch are taken in (runs of them at once,
/// by a TautFrontier), and it is solved again; on contact-free graphs that are no chain, the
/// first Newton steps of a projection solve once and leave the taut set to the next
/// linearization, which takes it from their multipliers and stretches (kQuickNewtonSteps,
/// stoppedEarly()). Edge ends that StartDirections marks take the start direction instead of J(x)
/// in the force balance; the symmetric matrix with J(x) then preconditions a few refinement passes
/// on the exact (unsymmetric) system (without contacts).
///
/// Contacts (ContactSet) are more rows of the same system, placed after their later vertex so
/// that a chain's system stays banded: a touching point's normal row (an equality while it
/// pushes, released when its multiplier would pull, taken in when the step would push the point
/// into the obstacle) and, while it sticks, two friction rows that hold it where it was; a point
/// whose friction would exceed mu m_n slides, with the known impulse mu m_n against its slip in
/// the right-hand side (m_n of the previous pass), and sticks again when its slip turns round.
class StiffNewtonStep {
 public:
  /// Moves `position` by one step and overwrites `multiplier` (0 for edges not taut). `taut`
  /// marks the edges taken as equalities (updated when edges are released); `movable` the edges
  /// that may take part; `inverse_mass` is 0 for pinned and kinematic vertices; `stretch_state`
  /// gives B_e and s_e per edge, and is switched where a taut edge's force crosses the one that
  /// reaches its breaking length.
  void apply(const std::vector<Eigen::Vector3d>& predicted, const std::vector<double>& inverse_mass,
             const EdgeSet& edges, const EdgeIncidence& incidence, EdgeStretchState& stretch_state,
             const std::vector<std::uint8_t>& movable, std::vector<std::uint8_t>& taut,
             std::vector<Eigen::Vector3d>& position, std::vector<double>& multiplier,
             ContactSet* contacts = nullptr, const StartDirections& start = {});
  /// How much the last apply() changed the contacts' impulses [-]: the largest change relative
  /// to the impulse (or, where larger, to the impulse that would move the free point by its
  /// length scale). The iteration has not converged while it exceeds the tolerance (a point at
  /// its friction bound may flip between sticking and sliding with the same impulse: the flags
  /// alone would never settle).
  double impulseChange() const { return impulse_change_; }
  /// Whether the last apply() was a quick Newton step (kQuickNewtonSteps) whose pivoting changed
  /// the taut set: its step solved a linearized problem whose complementarity is not exact
  /// (a taut edge may push, a slack one be stretched), and a projection must not end on it.
  bool stoppedEarly() const { return stopped_early_; }
  /// Never eliminates vertices from the system (VertexCondensation), for comparing the two.
  void forceFullSystems(bool force) { force_full_ = force; }
  /// Factorizes every system, never solving one with the last factorization
  /// (solveWithLastFactor()), for comparing the two.
  void forceFreshFactorizations(bool force) { force_fresh_ = force; }
  /// Threads the sparse factorizations may use [-] (PatternCachedLdlt::setThreads).
  void setThreads(int threads) {
    general_factorization_.setThreads(threads);
    condensed_factorization_.setThreads(threads);
    contact_factorization_.setThreads(threads);
  }
  /// Systems factorized since this object was made [-].
  long factorizations() const { return factorizations_; }
  /// Symbolic analyses of the sparse factorizations since this object was made [-]
  /// (PatternCachedLdlt::factorAnalyses()).
  long analyses() const {
    return general_factorization_.factorAnalyses() + condensed_factorization_.factorAnalyses() +
           contact_factorization_.factorAnalyses();
  }
  /// Systems listed straight into their factorization's analysed pattern since this object was
  /// made [-]: a fabric's systems, whose taut and idle rows list the same entries, once their
  /// layout was analysed.
  long directListings() const { return direct_listings_; }
  /// Systems begun straight into the analysed pattern whose entries did not follow its sequence,
  /// and were listed again as triplets, since this object was made [-]; sliding friction's
  /// unsymmetric systems not counted. Zero where addEdgeRows() and skipIdleEntries() agree.
  long directFallbacks() const { return direct_fallbacks_; }
  /// Newton steps taken since beginProjection() [-].
  int steps() const { return newton_steps_; }
  /// How far apart edge `e`'s push would have moved its ends where the last apply() of this
  /// projection released it from the taut set: (w_a + w_b) p, p minus its multiplier in the
  /// solve that released it [m]; 0 where it was not released.
  double releasedMove(std::size_t e) const {
    return e < released_move_.size() ? released_move_[e] : 0.0;
  }
  /// From now on in this projection, every Newton step pivots until its taut set holds.
  void pivotFully() { full_pivoting_ = true; }
  /// From now on in this projection, each Newton step's solve takes one pass of iterative
  /// refinement (refine()): for Newton steps that have stalled at the round-off of a solve that is
  /// not backward stable.
  void refineSolves() { refine_ = true; }
  /// Starts a projection's Newton steps of a step of `time_step` [s]: counts them from here
  /// (kStickingNewtonSteps), sets the contact rows' compliance (kContactCompliance) and the
  /// stretch per rest length [-] past which pivoting takes a slack edge in (`slack_tolerance`:
  /// the projection's, a tenth of its constraint tolerance, as in its fast iterations).
  void beginProjection(double time_step, double slack_tolerance) {
    newton_steps_ = 0;
    released_move_.clear();
    slack_tolerance_ = slack_tolerance;
    refine_ = false;
    full_pivoting_ = false;
    stopped_early_ = false;
    const double longer = time_step / kCompliantStep;
    compliance_ = longer > 1.0 ? kContactCompliance / (longer * longer) : kContactCompliance;
  }

 private:
  /// Whether edge e's force acts on its end b (or a) along its start direction.
  bool takesStartDirection(std::size_t e, bool end_b) const;
  /// residual_ = rhs_ - A solution_ for the exact system with start directions [mixed units].
  void exactResidual(const EdgeSet& edges, const std::vector<Eigen::Vector3d>& position,
                     const std::vector<double>& inverse_mass, const std::vector<double>& multiplier,
                     const EdgeStretchState& stretch_state);
  /// Solves the assembled symmetric system for `rhs`, into `result`.
  bool solveAssembled(const Eigen::VectorXd& rhs, Eigen::VectorXd& result);
  /// One pass of iterative refinement of solution_ on the assembled matrix (matrix_, or the
  /// banded factorization's), `solve(rhs,
  /// result)` solving with the factors already computed. A wrap's contact system is factorized
  /// without pivoting (LDL^T) or with pivots chosen for sparsity (LU), which is not backward
  /// stable at (omega dt)^2 ~ 1e7: the force balances then stalled at 1e-13 of their terms, 500
  /// times the round-off of evaluating them; one pass brings them to that round-off.
  template <typename Solve>
  bool refine(const Solve& solve) {
    if (dense_band_ && !unsymmetric_) {
      dense_band_factorization_.multiply(solution_, residual_);
      residual_ = rhs_ - residual_;
    } else {
      residual_ = rhs_ - matrix_ * solution_;
    }
    if (!solve(residual_, correction_)) return false;
    solution_ += correction_;
    return solution_.allFinite();
  }
  /// Assembles and solves the system for the current `taut` set into solution_.
  bool solve(const std::vector<Eigen::Vector3d>& predicted, const std::vector<double>& inverse_mass,
             const EdgeSet& edges, const EdgeIncidence& incidence,
             const EdgeStretchState& stretch_state, const std::vector<std::uint8_t>& taut,
             const std::vector<Eigen::Vector3d>& position, const std::vector<double>& multiplier,
             const ContactSet* contacts);
  /// Numbers the rows (vertex_row_, edge_row_, idle_row_, the contacts'); returns their count.
  int numberRows(const std::vector<double>& inverse_mass, const EdgeSet& edges,
                 const EdgeIncidence& incidence, const std::vector<std::uint8_t>& taut,
                 const ContactSet* contacts);
  /// Adds `value` to entry (row, col) of the system: into the dense band (dense_band_, the
  /// lower triangle), straight into the analysed pattern (direct_) or as a triplet (both
  /// triangles listed); a condensed system's rows are its reduced ones.
  void addEntry(int row, int col, double value) {
    if (rhs_only_) return;
    if (dense_band_) {
      dense_band_factorization_.add(row, col, value);
      return;
    }
    if (condensing_) {
      row = condensation_.reducedRow(row);
      col = condensation_.reducedRow(col);
      if (row < 0 || col < 0) return;
    }
    if (direct_) {
      direct_listed_ = direct_listed_ && generalFactorization().addDirect(row, col, value);
    } else {
      triplets_.emplace_back(row, col, value);
    }
  }
  /// The general path's factorization of this solve: the condensed or the full system's.
  PatternCachedLdlt& generalFactorization() {
    if (condensing_) return condensed_factorization_;
    return with_contacts_ ? contact_factorization_ : general_factorization_;
  }
  /// Whether entries go straight into the analysed pattern of the full (not condensed) system
  /// in its sequence (PatternCachedLdlt::addDirect): addBlock()'s and skipIdleEntries()' path.
  bool listsDirectly() const { return !rhs_only_ && direct_ && !condensing_ && !dense_band_; }
  /// Passes over the entries addEdgeRows() lists for an idle row (all zeros, but its diagonal)
  /// whose ends have vertex rows `ra` and `rb` (-1 for none) in the analysed sequence.
  void skipIdleEntries(int ra, int rb);
  /// Adds a 3 x 3 block at (row, col) (addEntry).
  void addBlock(int row, int col, const Eigen::Matrix3d& block);
  /// The half bandwidth [rows] of a chain's system as numbered by numberRows().
  int chainBandwidth(const EdgeSet& edges) const;
  /// Adds the free vertices' mass rows to the system and rhs_.
  void addVertexRows(const std::vector<Eigen::Vector3d>& predicted,
                     const std::vector<double>& inverse_mass,
                     const std::vector<Eigen::Vector3d>& position);
  /// Adds the taut (and idle) edges' rows and geometric stiffness to triplets_ and rhs_; false
  /// for a taut edge of zero length.
  bool addEdgeRows(const EdgeSet& edges, const EdgeStretchState& stretch_state,
                   const std::vector<Eigen::Vector3d>& position,
                   const std::vector<double>& multiplier);
  /// Chooses the vertices to eliminate (condensation_, condensing_) on a contact-free graph that
  /// is no chain, where ends take start directions: an edge has no geometric stiffness where
  /// each end is a support or takes its start direction.
  void chooseCondensation(const EdgeSet& edges, const EdgeIncidence& incidence,
                          const std::vector<double>& inverse_mass, int rows);
  /// matrix_ from triplets_.
  void assembleMatrix(int rows);
  /// Solves the system with sliding friction columns (LU) into solution_.
  bool solveUnsymmetric(int rows);
  /// Factorizes the symmetric system (banded or general) and solves it into solution_.
  bool solveSymmetric(int rows);
  /// Whether this solve's system has the rows, taut set and eliminated vertices of the last one
  /// the general path factorized (LastFactorization), so that solveWithLastFactor() may use it.
  bool lastFactorFits(const ContactSet* contacts) const;
  /// Solves this solve's system by iterative refinement on the exact system (exactResidual()),
  /// each pass solved with the last factorization: only the right-hand side is assembled. A
  /// projection's first Newton step starts the passes from the linearization's multipliers after
  /// a solve that took the last factors too (last_solve_reused_), others from zero. False when
  /// kReusePasses do not bring the correction below kReuseTolerance of the solution (the caller
  /// then assembles and factorizes).
  bool solveWithLastFactor(int rows, const std::vector<Eigen::Vector3d>& predicted,
                           const std::vector<double>& inverse_mass, const EdgeSet& edges,
                           const EdgeStretchState& stretch_state,
                           const std::vector<Eigen::Vector3d>& position,
                           const std::vector<double>& multiplier);
  /// Remembers this solve's layout as the general path's last factorized one.
  void rememberFactorization();
  /// Refines solution_ on the exact system where edge ends take their start directions.
  bool refineOnStartDirections(const EdgeSet& edges, const std::vector<Eigen::Vector3d>& position,
                               const std::vector<double>& inverse_mass,
                               const std::vector<double>& multiplier,
                               const EdgeStretchState& stretch_state);
  /// Adds the contacts' rows (numbered by solve) to triplets_ and rhs_.
  void addContactRows(const ContactSet& contacts, const std::vector<double>& inverse_mass,
                      const std::vector<Eigen::Vector3d>& position);
  /// Orders the contacts by their later vertex (contact_order_, contact_start_).
  void sortContacts(const ContactSet& contacts, std::size_t num_vertices);
  /// Writes each contact's normal multiplier and friction impulse from the last solution.
  void storeContactImpulses(ContactSet& contacts) const;
  /// Pivots the contacts' normal rows and the stick / slide state of each friction tangent
  /// after a pass (a box LCP per tangent, its bound mu m_n from the same pass, ContactSet);
  /// true when any changed or a sliding bound moved.
  bool pivotContacts(ContactSet& contacts, const std::vector<double>& inverse_mass,
                     const std::vector<Eigen::Vector3d>& position);
  /// Makes contact `i` (`c`) slide against its slip over the step (after this pass's `move` of
  /// its point [m]) for the rest of this apply, without friction rows (kMaxNormalFlips).
  void slideAlongSlip(std::size_t i, Contact& c, const std::vector<Eigen::Vector3d>& position,
                      const Eigen::Vector3d& move);
  /// Whether contact `c` has friction rows or sliding friction in this apply.
  static bool hasFriction(const Contact& c);
  /// The friction impulse [kg m] on the yarn of contact `i` (`c`) in the last solution.
  Eigen::Vector3d frictionImpulse(std::size_t i, const Contact& c) const;
  /// Keeps each contact's impulse before the solve (impulseChange()).
  void rememberImpulses(const ContactSet& contacts);
  /// Sets impulse_change_ from the impulses stored after the solve.
  void measureImpulseChange(const ContactSet& contacts, const std::vector<double>& inverse_mass);
  /// The solved step's move of contact `c`'s point [m].
  Eigen::Vector3d pointMove(const Contact& c) const;

  /// Length minus base length [m] of a slack edge after the solved step, to first order.
  double linearizedStretch(const EdgeSet& edges, const EdgeStretchState& stretch_state,
                           std::size_t e, const std::vector<Eigen::Vector3d>& position) const;
  /// How far apart edge `e`'s pass multiplier, where it pushes, would move its ends: minus it
  /// times w_a + w_b [m].
  double pushMove(const std::vector<double>& inverse_mass, const EdgeSet& edges,
                  std::size_t e) const {
    return -pass_multiplier_[e] *
           (inverse_mass[edges.vertex_a[e]] + inverse_mass[edges.vertex_b[e]]);
  }

  static constexpr int kMaxPivotingPasses = 30;  ///< re-solves after changing the taut set
  /// Times an edge may leave the taut set in one apply() [-]; then it stays taut (its multiplier
  /// read as 0 if it pushes) and the next linearization decides again. The linearized problem
  /// need not have a solution the pivoting reaches: in a torn patch flapping from its corners one
  /// edge left with a push of 1e-10 kg m and was stretched 2 um once slack, pass after pass, 30
  /// factorizations in each of the step's Newton steps.
  static constexpr int kMostLeaves = 2;
  std::vector<std::uint8_t> leaves_;   ///< per edge: times it left in this apply() [-]
  std::vector<double> released_move_;  ///< see releasedMove() [m]
  /// Newton steps of a projection that solve once on a contact-free graph that is no chain
  /// (quick Newton steps): solving every intermediate linearization's complementarity problem
  /// exactly is wasted work, as the next linearization moves the taut set again. Pivoted once per
  /// linearization (a primal-dual active-set, or semismooth Newton, iteration), a plain step of
  /// the 32 x 32 trouser tear took 5-6 Newton steps of one factorization each instead of 3 of
  /// 5-12. Later Newton steps pivot fully, so that an iteration whose taut set cycles still
  /// ends [-].
  static constexpr int kQuickNewtonSteps = 8;
  /// Solves in a row that must have eliminated the same vertices as the one before them for the
  /// next to be condensed: a reduced system's analysis (a new ordering) pays only over many
  /// solves. In a fabric that tears and whips, the slow vertices change every step and the start
  /// directions are dropped within LengthConstraintProjection::kStartDirectionNewtonSteps; in a
  /// held fabric they stay the same for hundreds of steps [-].
  static constexpr int kCondensedAfterSolves = 3;
  bool full_pivoting_ = false;  ///< see pivotFully()
  bool stopped_early_ = false;  ///< see stoppedEarly()
  /// A contact's gap, slip or move (per its length scale) below which it counts as none [-].
  static constexpr double kSlackTolerance = 1e-9;
  double slack_tolerance_ = kSlackTolerance;  ///< see beginProjection()
  /// Every edge joins consecutive vertices (chains): the rows are then banded and factorized in
  /// natural order, O(N); other graphs use Eigen's default (AMD) ordering.
  bool banded_ = false;
  /// Factorization for banded systems without contact rows (dense band storage, natural order).
  BandedLdlt dense_band_factorization_;
  bool dense_band_ = false;  ///< the current system is assembled into dense_band_factorization_
  /// Factorization for banded systems with contact rows, kept so its storage is reused; copies
  /// start without one.
  struct SparseBandFactorization {
    SparseBandFactorization() = default;
    SparseBandFactorization(const SparseBandFactorization&) {}
    SparseBandFactorization& operator=(const SparseBandFactorization&) { return *this; }
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>>
        ldlt;
  };
  SparseBandFactorization sparse_band_factorization_;
  /// LU for systems with sliding friction (unsymmetric), kept for its storage; copies start
  /// without one.
  struct SlidingFactorization {
    SlidingFactorization() = default;
    SlidingFactorization(const SlidingFactorization&) {}
    SlidingFactorization& operator=(const SlidingFactorization&) { return *this; }
    Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
  };
  SlidingFactorization sliding_factorization_;
  bool unsymmetric_ = false;  ///< the assembled system has sliding friction columns
  /// Factorization for other graphs, its symbolic analysis kept while the pattern holds.
  PatternCachedLdlt general_factorization_;
  /// The same for condensed systems: a condensed and a full system keep their analyses side by
  /// side.
  PatternCachedLdlt condensed_factorization_;
  /// The same for systems with contact rows, which keeps the analyses of the few systems a
  /// step's pivoting passes go through (PatternCachedLdlt::keepAnalyses).
  PatternCachedLdlt contact_factorization_ = keptAnalyses(kContactAnalyses);
  /// Analyses contact_factorization_ keeps [-].
  static constexpr std::size_t kContactAnalyses = 8;
  /// A PatternCachedLdlt that keeps `most` analyses.
  static PatternCachedLdlt keptAnalyses(std::size_t most) {
    PatternCachedLdlt factorization;
    factorization.keepAnalyses(most);
    return factorization;
  }
  bool with_contacts_ = false;   ///< this solve's system has contact rows
  double impulse_change_ = 0.0;  ///< see impulseChange()
  bool refine_ = false;          ///< see refineSolves()
  int newton_steps_ = 0;         ///< Newton steps since beginProjection() [-]
  /// Newton steps of a projection in which a sliding tangent may stick again; after them
  /// sliding is final for the rest of the projection (against a cycle of two Newton iterates,
  /// a point sticking in one and sliding in the next) [-].
  static constexpr int kStickingNewtonSteps = 10;
  std::vector<Eigen::Vector3d> previous_impulse_;  ///< per contact, before the solve [kg m]
  std::vector<int> vertex_row_;  ///< first row of each free vertex, -1 for supports
  std::vector<int> edge_row_;    ///< row of each taut edge, -1 otherwise
  /// Row of each slack or torn edge with a free end (not banded), -1 otherwise.
  std::vector<int> idle_row_;
  /// Eliminates the vertices no edge stiffens from the general path's system (solveAssembled
  /// then condenses and expands); a held fabric's Newton system shrinks to about one row an edge.
  VertexCondensation condensation_;
  /// This solve's system is condensed: only when the last kCondensedAfterSolves solves would
  /// have eliminated the same vertices, so that a scene whose slow vertices change from step to
  /// step keeps the full system's analysis rather than analysing a new reduced one in every step.
  bool condensing_ = false;
  /// Solves in a row, up to this one, that would have eliminated the same vertices as the
  /// solve before them, counted up to kCondensedAfterSolves [-].
  int same_eliminated_ = 0;
  bool force_full_ = false;                      ///< see forceFullSystems()
  bool force_fresh_ = false;                     ///< see forceFreshFactorizations()
  long factorizations_ = 0;                      ///< see factorizations()
  long direct_listings_ = 0;                     ///< see directListings()
  long direct_fallbacks_ = 0;                    ///< see directFallbacks()
  std::vector<std::uint8_t> last_eliminated_;    ///< the vertices the last solve would eliminate
  std::vector<int> system_row_;                  ///< per edge: its taut or idle row, else -1
  std::vector<std::uint8_t> plain_;              ///< per edge: no geometric stiffness (condensing)
  std::vector<Eigen::Vector3d> edge_direction_;  ///< per edge: n_e in this system, 0 if idle
  const std::vector<double>* inverse_mass_ = nullptr;  ///< this solve's w_v [1/kg]
  Eigen::VectorXd reduced_rhs_;                        ///< a right-hand side condensed
  Eigen::VectorXd reduced_solution_;                   ///< its solution
  /// This solve's entries go straight into generalFactorization()'s pattern (addEntry()), not
  /// into triplets_.
  bool direct_ = false;
  /// Every entry added so far was the next of generalFactorization()'s last sequence.
  bool direct_listed_ = false;
  std::vector<Eigen::Triplet<double>> triplets_;
  Eigen::SparseMatrix<double> matrix_;
  Eigen::VectorXd rhs_;
  Eigen::VectorXd solution_;
  Eigen::VectorXd residual_;    ///< refinement residual
  Eigen::VectorXd correction_;  ///< refinement correction
  StartDirections start_;       ///< the start directions of the current apply
  /// Refinement passes on the exact system when some ends take start directions.
  static constexpr int kRefinementPasses = 2;
  /// The layout of the system the general path last factorized (not that of a contact system):
  /// a settled scene's next system differs from it only by the small change of its directions,
  /// geometric stiffness and compliances, and is solved by refinement with its factors. Copies
  /// start without one, as the factorizations do.
  struct LastFactorization {
    LastFactorization() = default;
    LastFactorization(const LastFactorization&) {}
    LastFactorization& operator=(const LastFactorization&) {
      valid = false;
      return *this;
    }
    bool valid = false;      ///< the factors are those of this layout
    bool condensed = false;  ///< the factorization was of the condensed system
    std::vector<int> vertex_row;
    std::vector<int> edge_row;
    std::vector<int> idle_row;
    std::vector<std::uint8_t> eliminated;  ///< the eliminated vertices (condensed)
  };
  LastFactorization last_factorization_;
  /// Refinement passes a solve with the last factorization may take before it gives up [-].
  static constexpr int kReusePasses = 4;
  /// Largest last correction, relative to the solution, that ends such a solve [-]. A freshly
  /// factorized system's kRefinementPasses end there or above in most solves (on start
  /// directions the symmetric system is itself only a preconditioner: a fabric held at its
  /// corners ended at 1e-2 to 1e-7 of the solution, most near 1e-3); the projection's own
  /// convergence test then decides whether the iterate is done.
  static constexpr double kReuseTolerance = 1e-3;
  /// Solves with a fitting last factorization to leave out before trying one again after it did
  /// not converge: doubled (plus one) at each such try, 0 after one that converged [-].
  int reuse_backoff_ = 0;
  int reuse_wait_ = 0;  ///< fitting solves still to leave out [-]
  /// Whether the last solve took the last factors (solveWithLastFactor()) rather than a fresh
  /// factorization (a scene that changes slowly; after a factorization it may be jerking) [-].
  bool last_solve_reused_ = false;
  /// Most solves left out between two tries [-].
  static constexpr int kMostReuseWait = 63;
  /// Only the right-hand side is assembled (addEntry() and addBlock() add nothing).
  bool rhs_only_ = false;
  std::vector<double> pass_multiplier_;  ///< multiplier of each edge in a pass's solution [kg*m]
  std::vector<double> stretch_;          ///< a pass's linearized stretch of slack edges [m]
  TautFrontier frontier_;                ///< takes in runs of slack edges at once
  /// Contact indices sorted by their later vertex, and where each vertex's run starts.
  std::vector<std::uint32_t> contact_order_;
  std::vector<std::uint32_t> contact_start_;
  std::vector<std::uint32_t> contact_fill_;  ///< scratch of sortContacts
  std::vector<int> normal_row_;              ///< per contact: its normal row, -1 when inactive
  /// Per contact and tangent: its friction row while it sticks, -1 otherwise.
  std::vector<std::array<int, Contact::kFrictionDirections>> friction_row_;
  /// Per contact: how often its tangents switched between sticking and sliding in this apply.
  std::vector<int> friction_flips_;
  /// Per contact: how often its normal row was released or taken in in this apply.
  std::vector<int> normal_flips_;
  /// Per contact: slides against its slip, without friction rows, for the rest of this apply
  /// (kMaxNormalFlips).
  std::vector<std::uint8_t> slide_only_;
  /// Least share of the largest tangential slip along which a point that slides against its
  /// slip (slideAlongSlip) takes friction [-]: a tangent that hardly slips gets none rather
  /// than a sideways push of mu m_n.
  static constexpr double kSlideShare = 0.5;
  /// Compliance of contact rows relative to the row's own w sum [-]: keeps the system
  /// quasi-definite where contact rows are (nearly) dependent, e.g. two obstacles on a vertex.
  static constexpr double kContactCompliance = 1e-12;
  /// Longest step with the full kContactCompliance [s]. A row's compliance pushes its point in
  /// by the compliance times m_n, which grows as dt^2 (m_n = force dt^2): in longer steps the
  /// compliance falls as 1 / dt^2, so that the penetration stays that of this step (at dt 1e-2
  /// a 2 pi wrap at 0.9 of the capstan law sat 1.0e-6 of a chord deep, past the tolerance).
  static constexpr double kCompliantStep = 1e-3;
  double compliance_ = kContactCompliance;  ///< this projection's, relative to w [-]
  /// Relative margin on the friction bound, so a point right at it does not flip on round-off.
  static constexpr double kFrictionMargin = 1e-9;
  /// Switches of a contact's tangents between sticking and sliding within one Newton step;
  /// after that a tangent may still start to slide but not stick again until the next Newton
  /// step (against cycling; the friction never exceeds its bound).
  static constexpr int kMaxFrictionFlips = 4;
  /// Releases and take-ins of a contact's normal row within one Newton step after which it
  /// slides against its slip until the next Newton step (against cycling).
  static constexpr int kMaxNormalFlips = 4;
  /// Relative change of a sliding impulse that needs another Newton step [-] (its bound and
  /// direction follow the iterate, converging with it).
  static constexpr double kFrictionTolerance = 1e-6;
};

}  // namespace yarn_tearing
