#pragma once

#include <dynamic_reconfigure/server.h>
#include <ros/ros.h>
#include <std_srvs/Empty.h>
#include <std_srvs/SetBool.h>
#include <tf2_ros/buffer.h>
#include <visualization_msgs/MarkerArray.h>

#include <atomic>
#include <boost/thread/recursive_mutex.hpp>
#include <memory>
#include <mutex>
#include <optional>

#include "yarn_tearing/AppliedForce.h"
#include "yarn_tearing/FabricStateArray.h"
#include "yarn_tearing/GetBreakEvents.h"
#include "yarn_tearing/Grasp.h"
#include "yarn_tearing/YarnStateArray.h"
#include "yarn_tearing/YarnTearingConfig.h"
#include "yarn_tearing/core/simulation/simulator.hpp"
#include "yarn_tearing/ros/break_event_log.hpp"
#include "yarn_tearing/ros/frame_transformer.hpp"
#include "yarn_tearing/ros/input_handler.hpp"
#include "yarn_tearing/ros/marker_builder.hpp"
#include "yarn_tearing/ros/obstacle_tracker.hpp"
#include "yarn_tearing/ros/rate_schedule.hpp"
#include "yarn_tearing/ros/service_thread.hpp"
#include "yarn_tearing/ros/simulation_config.hpp"
#include "yarn_tearing/ros/simulation_diagnostics.hpp"
#include "yarn_tearing/ros/stamp_clock.hpp"
#include "yarn_tearing/ros/step_scheduler.hpp"
#include "yarn_tearing/ros/support_wrench_publisher.hpp"
#include "yarn_tearing/ros/tf_input.hpp"
#include "yarn_tearing/ros/warning_throttle.hpp"
#include "yarn_tearing/ros/wrench_topics.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// The yarn_tearing_node: steps a Simulator at real_time_factor and connects it to ROS.
///
/// Topics (relative to the node's namespace): subscribes applied_force, grasp; publishes
/// yarn_states, yarn_markers (with the obstacles), the holders' wrenches (~grasp_wrench/...,
/// ~pin_wrench/...) and the obstacles' contact wrenches (~obstacles/<name>/wrench) at
/// publish_rate, break_events (one message per break, right after
/// the step that tore), yarn_materials (latched YAML), /clock when publish_clock, /diagnostics.
/// Services: ~reset (std_srvs/Empty), ~set_paused (std_srvs/SetBool); dynamic_reconfigure
/// (cfg/YarnTearing.cfg) in the private namespace.
/// Threads: run() steps, publishes and serves the inputs (applied_force, grasp,
/// dynamic_reconfigure) between stepping cycles; the services and a diagnostics timer run on a
/// ServiceThread, so they answer while a step runs, however long. mutex_ guards everything the two
/// share; run() holds it except inside Simulator::step() and while it waits for callbacks. While a
/// step runs longer than a publishing period, the last states are re-sent at publish_rate. A
/// ~reset or ~set_paused that comes during a step is applied as soon as that step ends (after its
/// break events are published), before anything else. Shared by yarn_tearing_node (node_runner)
/// and the nodelet (YarnTearingNodelet).
class YarnTearingNode {
 public:
  /// Builds the simulator; throws std::invalid_argument when the core rejects the configuration.
  YarnTearingNode(ros::NodeHandle nh, ros::NodeHandle private_nh, const SimulationConfig& config);
  /// Stops the service thread before anything it uses is destroyed.
  ~YarnTearingNode();
  YarnTearingNode(const YarnTearingNode&) = delete;
  YarnTearingNode& operator=(const YarnTearingNode&) = delete;

  /// Steps, publishes and serves the callbacks of `nh`'s callback queue (the global one unless
  /// set) until ROS shuts down or requestStop() is called.
  void run();
  /// Makes run() return after its current cycle (thread-safe; for the nodelet).
  void requestStop() { stop_requested_ = true; }

 private:
  /// What a throttled warning is about: one throttle key per source and reason.
  enum class WarningSource : std::size_t { kAppliedForce, kGrasp, kRestoredYarn, kCount };

  void onAppliedForce(const AppliedForce::ConstPtr& msg);
  void onGrasp(const Grasp::ConstPtr& msg);
  /// Warns, throttled per topic and reason, that an input message was refused.
  /// Throttle key of a source and a reason (index of RefusalReason; 0 for kRestoredYarn).
  static std::size_t warningKey(WarningSource source, std::size_t reason);
  void warnRefused(WarningSource source, const char* topic, int vertex, const InputRejected& e);
  /// After a step that restored yarns: forgets their inputs, logs one error (throttled).
  void reportRestoredYarns();
  /// ~reset (service thread): at once between steps, else when the step under way ends.
  bool onReset(std_srvs::Empty::Request& request, std_srvs::Empty::Response& response);
  /// Back to the initial scene (mutex_ held, no step under way).
  void resetNow();
  /// Applies a ~reset or ~set_paused that came during the step that just ended (mutex_ held);
  /// true when one was applied (the cycle then ends: pacing was restarted).
  bool applyPendingRequests();
  /// Service thread, every kStepWatchPeriod: while a step runs, re-sends the last yarn_states and
  /// fabric_states at publish_rate (wall-timed publishing only) and keeps /diagnostics going.
  void onStepWatch();
  /// Simulated time [s] as of the last finished step (readable while a step runs).
  double simulatedTime() const { return stepping_ ? time_before_step_ : simulator_.time(); }
  /// ~get_break_events: the logged break events from request.first on.
  bool onGetBreakEvents(GetBreakEvents::Request& request, GetBreakEvents::Response& response);
  bool onSetPaused(std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response);
  /// dynamic_reconfigure: applies real_time_factor, publish_rate, air_damping, regularization,
  /// breaking_enabled and paused between steps.
  void onReconfigure(YarnTearingConfig& tuning, std::uint32_t level);
  /// The live-tunable values as they are now.
  YarnTearingConfig currentTuning() const;
  void setPaused(bool paused);
  /// Restarts the publishing schedule on the clock publish_rate counts in (wall or simulated).
  void restartPublishSchedule();

  /// Takes the steps that are due (or steps for a wall budget when as fast as possible); sets
  /// behind_ when steps are still due after the budget.
  void stepCycle();
  /// True when the next step would outrun a followed tf frame's samples (a grasp or an obstacle
  /// would stand still) and the loop has waited less than kFrameWait for a newer one: the cycle
  /// then ends and the loop polls for tf instead of stepping.
  bool waitForFrames();
  /// Adds the wall time since `since` [s] to `stage` in the diagnostics; returns now [s].
  double recordStage(LoopStage stage, double since);
  /// One physics step (mutex_ released while the simulator steps); `fraction` (0..1] of the cycle
  /// done after it, for grasp interpolation. False when a request that came during the step was
  /// applied after it (the cycle must end).
  bool stepOnce(double fraction);
  void publishBreakEvents();
  void publishState();
  /// Builds the states to re-send during a long step from the simulator as it is now (at start
  /// and after a reset; otherwise publishState() keeps what it published, and only that).
  void keepStatesToResend();
  /// The force [N] the yarns exerted on each obstacle in the last step and its torque [N m] about
  /// frame_id's origin, in frame_id, on ~obstacles/<name>/wrench (only when subscribed).
  void publishObstacleWrenches(const ros::Time& stamp);
  /// yarn_markers: the scene's and the obstacles' markers.
  visualization_msgs::MarkerArray buildMarkers(const ros::Time& stamp);
  void publishClock();
  /// Anchors the step pacing and the stamps to now (start, reset, resume).
  void restartPacing();
  /// Stamp of simulated instant `sim_time` [s] (see StampClock).
  ros::Time stampOf(double sim_time) const;
  /// Wall seconds [s] until the loop must wake up again.
  double idleTimeout() const;
  /// Pacing figures for the diagnostics.
  PacingStatus pacingStatus() const;

  SimulationConfig config_;
  ros::NodeHandle nh_;
  ros::NodeHandle private_nh_;
  Simulator simulator_;
  tf2_ros::Buffer tf_buffer_;
  TfInput tf_input_;  ///< /tf and /tf_static into tf_buffer_
  FrameTransformer frames_;
  InputHandler inputs_;
  ObstacleTracker obstacles_;
  MarkerBuilder markers_;
  StepScheduler scheduler_;
  StampClock stamps_;
  RateSchedule publish_schedule_;  ///< wall or simulated seconds, see NodeSettings
  SimulationDiagnostics diagnostics_;
  WarningThrottle refusal_warnings_;
  SupportWrenchPublisher wrenches_;
  WrenchTopics obstacle_wrenches_;  ///< ~obstacles/<name>/wrench
  BreakEventLog break_log_;         ///< what break_events published since start or ~reset
  ros::Publisher states_pub_;
  ros::Publisher fabric_states_pub_;  ///< only when the scene has fabrics
  ros::Publisher breaks_pub_;
  ros::Publisher markers_pub_;
  ros::Publisher materials_pub_;
  ros::Publisher clock_pub_;
  ros::Subscriber force_sub_;
  ros::Subscriber grasp_sub_;
  /// Guards what the service thread shares with run(); run() holds it through loop_lock_.
  std::mutex mutex_;
  std::unique_lock<std::mutex> loop_lock_{mutex_, std::defer_lock};
  bool stepping_ = false;              ///< Simulator::step() under way (mutex_ released)
  double time_before_step_ = 0.0;      ///< [s] simulated time when it began
  double step_started_ = 0.0;          ///< [s] wall time when it began
  bool reset_pending_ = false;         ///< ~reset came during the step under way
  std::optional<bool> pause_pending_;  ///< ~set_paused came during the step under way
  ServiceThread services_;             ///< ~reset, ~set_paused, ~get_break_events, diagnostics
  ros::WallTimer step_watch_timer_;    ///< on services_
  /// The last states published or kept (re-sent while a step runs).
  YarnStateArray::ConstPtr last_states_;
  FabricStateArray::ConstPtr last_fabric_states_;
  ros::ServiceServer reset_srv_;
  ros::ServiceServer pause_srv_;
  ros::ServiceServer break_log_srv_;  ///< ~get_break_events
  bool paused_ = false;
  bool behind_ = false;              ///< the last cycle ended with steps still due: do not idle
  bool waiting_for_frames_ = false;  ///< the last cycle ended to wait for a frame's sample
  double frame_wait_start_ = -1.0;   ///< [s] wall, since when it waits; negative: not waiting
  std::atomic<bool> stop_requested_{false};
  boost::recursive_mutex reconfigure_mutex_;
  std::unique_ptr<dynamic_reconfigure::Server<YarnTearingConfig>> reconfigure_;
};

}  // namespace ros_layer
}  // namespace yarn_tearing
