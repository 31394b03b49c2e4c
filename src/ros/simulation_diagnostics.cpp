#include "yarn_tearing/ros/simulation_diagnostics.hpp"

#include <algorithm>
#include <cmath>

#include "yarn_tearing/ros/clipped_text.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

constexpr double kSlowFraction = 0.9;  ///< achieved / target factor below which we warn
/// Shortest window [s, wall] over which the achieved factor is measured: a window cut short by a
/// reset or a pause holds too few steps to say more than the step granularity.
constexpr double kMinWindow = 0.2;
constexpr double kMinPeriod = 0.01;  ///< [s] shortest ~diagnostic_period honoured
/// [s] wall a step in progress may run before a report says so in its summary (WARN).
constexpr double kLongStep = 0.5;

}  // namespace

const char* stageName(LoopStage stage) {
  switch (stage) {
    case LoopStage::kTargets:
      return "grasp and obstacle targets";
    case LoopStage::kPhysics:
      return "physics step";
    case LoopStage::kPublishing:
      return "publishing";
    case LoopStage::kCallbacks:
      return "callbacks";
    case LoopStage::kFrameWait:
      return "waiting for tf frames";
    case LoopStage::kCount:
      break;
  }
  return "none";
}

SimulationDiagnostics::SimulationDiagnostics(const ros::NodeHandle& nh,
                                             const ros::NodeHandle& private_nh)
    : updater_(nh, private_nh), schedule_(1.0 / std::max(updater_.getPeriod(), kMinPeriod)) {
  updater_.setHardwareID("none");
  updater_.add("simulation", this, &SimulationDiagnostics::report);
}

void SimulationDiagnostics::recordStep(const StepHealth& health, const Scene& scene) {
  for (std::uint32_t yarn : health.restored_yarns) {
    ++restorations_;
    last_restored_ = clipped(scene.yarns[yarn].name);
  }
  ++steps_;
  max_iterations_ = std::max(max_iterations_, health.projection_iterations);
  max_violation_ = std::max(max_violation_, health.max_constraint_violation);
  max_residual_ = std::max(max_residual_, health.tension_residual);
  unconverged_ += health.projection_converged ? 0 : 1;
  substepped_ += health.substeps > 1 ? 1 : 0;
  factorizations_ += static_cast<std::uint64_t>(std::max(health.factorizations, 0));
  analyses_ += static_cast<std::uint64_t>(std::max(health.analyses, 0));
  finite_ = finite_ && std::isfinite(health.max_constraint_violation) &&
            std::isfinite(health.tension_residual);
}

void SimulationDiagnostics::update(double wall_now, const PacingStatus& pacing) {
  pacing_ = pacing;
  wall_now_ = wall_now;
  if (window_wall_ < 0.0) {
    window_wall_ = wall_now;
    window_sim_ = pacing.simulated_time;
  }
  if (!started_) {
    schedule_.restart(wall_now);
    started_ = true;
  }
  // Wall-timed, not ROS-timed (Updater::update), so that /diagnostics goes on when ROS time
  // jumps back (a reset under /use_sim_time, a looping bag); a new restoration is said at once.
  const bool new_error = restorations_ > 0 && !error_reported_;
  if (schedule_.due(wall_now) || new_error) {
    updater_.force_update();
  }
}

void SimulationDiagnostics::restartWindow() { window_wall_ = -1.0; }

void SimulationDiagnostics::report(diagnostic_updater::DiagnosticStatusWrapper& status) {
  const double wall = wall_now_ - window_wall_;
  const double simulated = pacing_.simulated_time - window_sim_;
  const bool measured = wall >= kMinWindow && simulated >= 0.0;
  if (measured) {
    achieved_factor_ = simulated / wall;
    window_wall_ = wall_now_;
    window_sim_ = pacing_.simulated_time;
  }

  double busy = 0.0;  // [s] wall time of all stages
  std::size_t costliest = 0;
  for (std::size_t i = 0; i < stage_seconds_.size(); ++i) {
    busy += stage_seconds_[i];
    if (stage_seconds_[i] > stage_seconds_[costliest]) costliest = i;
  }
  const double share = busy > 0.0 ? stage_seconds_[costliest] / busy : 0.0;
  const std::string costliest_name = stageName(static_cast<LoopStage>(costliest));

  const bool dropped = pacing_.dropped_steps > reported_dropped_;
  const bool slow = measured && !pacing_.paused && pacing_.target_real_time_factor > 0.0 &&
                    achieved_factor_ < kSlowFraction * pacing_.target_real_time_factor;
  error_reported_ = restorations_ > 0;
  if (restorations_ > 0) {
    status.summary(diagnostic_msgs::DiagnosticStatus::ERROR,
                   "non-finite state: yarn '" + last_restored_ + "' restored to its initial state");
  } else if (!finite_) {
    status.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "non-finite step health");
  } else if (unconverged_ > 0) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, "length projection did not converge");
  } else if (pacing_.step_in_progress > kLongStep) {
    status.summary(
        diagnostic_msgs::DiagnosticStatus::WARN,
        "one step has been running for " + std::to_string(pacing_.step_in_progress) + " s");
  } else if (dropped || slow) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "slower than real_time_factor: " + std::to_string(pacing_.lag) + " s behind, " +
                       costliest_name + " takes " +
                       std::to_string(static_cast<int>(std::lround(100.0 * share))) +
                       " % of the loop");
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, pacing_.paused ? "paused" : "running");
  }
  status.add("simulated time [s]", pacing_.simulated_time);
  status.add("steps since last report", steps_);
  status.add("max projection iterations", max_iterations_);
  status.add("max constraint violation [-]", max_violation_);
  status.add("max tension residual [-]", max_residual_);
  status.add("unconverged steps", unconverged_);
  status.add("substepped steps", substepped_);
  const double steps = std::max(static_cast<double>(steps_), 1.0);
  status.add("mean factorizations per step [-]", static_cast<double>(factorizations_) / steps);
  status.add("mean symbolic analyses per step [-]", static_cast<double>(analyses_) / steps);
  status.add("target real-time factor", pacing_.target_real_time_factor);
  status.add("achieved real-time factor", achieved_factor_);
  status.add("dropped steps (total)", pacing_.dropped_steps);
  status.add("lag behind schedule [s]", pacing_.lag);
  status.add("step in progress [s]", pacing_.step_in_progress);
  status.add("costliest stage", busy > 0.0 ? costliest_name : std::string("none"));
  for (std::size_t i = 0; i < stage_seconds_.size(); ++i) {
    status.add(std::string("wall time share: ") + stageName(static_cast<LoopStage>(i)) + " [-]",
               busy > 0.0 ? stage_seconds_[i] / busy : 0.0);
  }
  const double physics = stage_seconds_[static_cast<std::size_t>(LoopStage::kPhysics)];
  status.add("mean physics step wall time [s]",
             steps_ > 0 ? physics / static_cast<double>(steps_) : 0.0);
  status.add("active forces", pacing_.active_forces);
  status.add("active grasps", pacing_.active_grasps);
  status.add("paused", pacing_.paused);
  status.add("yarns restored from a non-finite state", restorations_);

  reported_dropped_ = pacing_.dropped_steps;
  steps_ = 0;
  max_iterations_ = 0;
  max_violation_ = 0.0;
  max_residual_ = 0.0;
  unconverged_ = 0;
  substepped_ = 0;
  factorizations_ = 0;
  analyses_ = 0;
  finite_ = true;
  restorations_ = 0;
  stage_seconds_.fill(0.0);
}

}  // namespace ros_layer
}  // namespace yarn_tearing
