#include "yarn_tearing/ros/simulation_diagnostics.hpp"

#include <algorithm>
#include <cmath>

namespace yarn_tearing {
namespace ros_layer {
namespace {

constexpr double kSlowFraction = 0.9;  ///< achieved / target factor below which we warn

}  // namespace

SimulationDiagnostics::SimulationDiagnostics(const ros::NodeHandle& nh,
                                             const ros::NodeHandle& private_nh)
    : updater_(nh, private_nh) {
  updater_.setHardwareID("none");
  updater_.add("simulation", this, &SimulationDiagnostics::report);
}

void SimulationDiagnostics::recordStep(const StepHealth& health) {
  ++steps_;
  max_iterations_ = std::max(max_iterations_, health.projection_iterations);
  max_violation_ = std::max(max_violation_, health.max_constraint_violation);
  max_residual_ = std::max(max_residual_, health.tension_residual);
  unconverged_ += health.projection_converged ? 0 : 1;
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
  updater_.update();
}

void SimulationDiagnostics::report(diagnostic_updater::DiagnosticStatusWrapper& status) {
  const double wall = wall_now_ - window_wall_;
  const double simulated = pacing_.simulated_time - window_sim_;
  if (wall > 0.0 && simulated >= 0.0) {
    achieved_factor_ = simulated / wall;
  }
  window_wall_ = wall_now_;
  window_sim_ = pacing_.simulated_time;

  const bool dropped = pacing_.dropped_steps > reported_dropped_;
  const bool slow = !pacing_.paused && pacing_.target_real_time_factor > 0.0 &&
                    achieved_factor_ < kSlowFraction * pacing_.target_real_time_factor;
  if (!finite_) {
    status.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "non-finite step health");
  } else if (unconverged_ > 0) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, "length projection did not converge");
  } else if (dropped || slow) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, "slower than real_time_factor");
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, pacing_.paused ? "paused" : "running");
  }
  status.add("simulated time [s]", pacing_.simulated_time);
  status.add("steps since last report", steps_);
  status.add("max projection iterations", max_iterations_);
  status.add("max constraint violation [-]", max_violation_);
  status.add("max tension residual [-]", max_residual_);
  status.add("unconverged steps", unconverged_);
  status.add("target real-time factor", pacing_.target_real_time_factor);
  status.add("achieved real-time factor", achieved_factor_);
  status.add("dropped steps (total)", pacing_.dropped_steps);
  status.add("active forces", pacing_.active_forces);
  status.add("active grasps", pacing_.active_grasps);
  status.add("paused", pacing_.paused);

  reported_dropped_ = pacing_.dropped_steps;
  steps_ = 0;
  max_iterations_ = 0;
  max_violation_ = 0.0;
  max_residual_ = 0.0;
  unconverged_ = 0;
  finite_ = true;
}

}  // namespace ros_layer
}  // namespace yarn_tearing
