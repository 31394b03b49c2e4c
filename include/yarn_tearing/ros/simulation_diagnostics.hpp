#pragma once

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/node_handle.h>

#include <array>
#include <cstdint>
#include <string>

#include "yarn_tearing/core/model/scene.hpp"
#include "yarn_tearing/core/simulation/step_health.hpp"
#include "yarn_tearing/ros/rate_schedule.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// Snapshot of the node's pacing, reported with the step health.
struct PacingStatus {
  double simulated_time = 0.0;           ///< [s]
  double target_real_time_factor = 0.0;  ///< configured factor [-] (0 = as fast as possible)
  std::uint64_t dropped_steps = 0;       ///< steps skipped because the loop fell behind
  bool paused = false;
  std::size_t active_forces = 0;
  std::size_t active_grasps = 0;
  /// Simulated time the simulation is behind its real_time_factor schedule [s] (0 when on time,
  /// as fast as possible or paused); past max_lag (in wall seconds) steps are dropped instead.
  double lag = 0.0;
  /// Wall time [s] the step under way has taken so far (0 between steps: a report sent from the
  /// service thread while a step runs says how long it has run).
  double step_in_progress = 0.0;
};

/// The parts of the node's stepping loop whose wall time the diagnostics report.
enum class LoopStage : std::size_t {
  kTargets,     ///< grasp targets and obstacle poses: tf lookups, interpolation
  kPhysics,     ///< Simulator::step() (the core's stages 1-6)
  kPublishing,  ///< break events, states, markers, wrenches, /clock
  kCallbacks,   ///< incoming messages, services, dynamic_reconfigure
  kFrameWait,   ///< waiting for a newer sample of a followed tf frame (it would be outrun)
  kCount        ///< number of stages (not a stage)
};

/// Name of a stage in /diagnostics, e.g. "physics step".
const char* stageName(LoopStage stage);

/// Publishes /diagnostics (diagnostic_updater, period ~diagnostic_period [s, wall], default 1 s)
/// with the worst StepHealth since the last report and the real-time factor achieved over that
/// window. The period is kept in wall time, so reports go on through resets and ROS-time jumps.
/// Warns when the projection did not converge, steps were dropped or the achieved factor is below
/// 90 % of the target (measured since the last report, reset or pause/resume, over >= 0.2 s),
/// saying the lag and which stage of the loop (LoopStage) took the most wall time;
/// errors when a health value is not finite or a yarn was restored from a non-finite state (that
/// report goes out at once).
class SimulationDiagnostics {
 public:
  SimulationDiagnostics(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh);

  /// Accumulates one step's health (`scene` names the restored yarns).
  void recordStep(const StepHealth& health, const Scene& scene);
  /// Adds `seconds` [s, wall] spent in `stage` since the last report.
  void recordStage(LoopStage stage, double seconds) {
    stage_seconds_[static_cast<std::size_t>(stage)] += seconds;
  }
  /// Publishes when a period has passed; `wall_now` [s] (monotonic) measures the achieved factor.
  void update(double wall_now, const PacingStatus& pacing);
  /// Starts a new window of the achieved real-time factor at the next update (reset, pause,
  /// resume: simulated time jumped or stood still on purpose).
  void restartWindow();

 private:
  void report(diagnostic_updater::DiagnosticStatusWrapper& status);

  diagnostic_updater::Updater updater_;
  RateSchedule schedule_;  ///< wall seconds
  bool started_ = false;
  PacingStatus pacing_;
  // Accumulated since the last report.
  std::uint64_t steps_ = 0;
  int max_iterations_ = 0;
  double max_violation_ = 0.0;  ///< [-]
  double max_residual_ = 0.0;   ///< [-]
  std::uint64_t unconverged_ = 0;
  std::uint64_t substepped_ = 0;      ///< steps taken in substeps (a tear's recoil or a retry)
  std::uint64_t factorizations_ = 0;  ///< Newton systems factorized (StepHealth::factorizations)
  std::uint64_t analyses_ = 0;        ///< their symbolic analyses (StepHealth::analyses)
  bool finite_ = true;
  std::uint64_t restorations_ = 0;  ///< yarns restored from a non-finite state
  std::string last_restored_;       ///< name of the last one (clipped)
  bool error_reported_ = false;     ///< the last report said ERROR for restorations
  /// Wall time per LoopStage since the last report [s].
  std::array<double, static_cast<std::size_t>(LoopStage::kCount)> stage_seconds_{};
  // Window of the achieved real-time factor.
  double window_wall_ = -1.0;     ///< [s]
  double window_sim_ = 0.0;       ///< [s]
  double achieved_factor_ = 0.0;  ///< [-]
  double wall_now_ = 0.0;         ///< [s]
  std::uint64_t reported_dropped_ = 0;
};

}  // namespace ros_layer
}  // namespace yarn_tearing
