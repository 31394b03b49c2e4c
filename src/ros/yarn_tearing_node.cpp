#include "yarn_tearing/ros/yarn_tearing_node.hpp"

#include <ros/callback_queue.h>
#include <rosgraph_msgs/Clock.h>
#include <std_msgs/String.h>
#include <visualization_msgs/MarkerArray.h>
#include <yarn_tearing/BreakEvent.h>

#include <algorithm>
#include <boost/make_shared.hpp>
#include <chrono>
#include <cmath>

#include "yarn_tearing/YarnStateArray.h"
#include "yarn_tearing/ros/clipped_text.hpp"
#include "yarn_tearing/ros/materials_description.hpp"
#include "yarn_tearing/ros/message_conversion.hpp"
#include "yarn_tearing/ros/obstacle_markers.hpp"
#include "yarn_tearing/ros/parameter_bounds.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

constexpr double kCyclePeriod = 0.005;  ///< [s] wall: longest sleep between stepping cycles
constexpr double kStepBudget = 0.02;    ///< [s] wall: longest stepping before serving callbacks
/// [s] wall: longest the loop waits for a newer sample of a followed frame that it would otherwise
/// outrun (its follower would stand still); then it steps on.
constexpr double kFrameWait = 0.5;
constexpr double kFramePoll = 0.001;  ///< [s] wall: sleep while waiting for a frame's sample
/// [s] wall between the service thread's looks at a step under way (states, /diagnostics).
constexpr double kStepWatchPeriod = 0.005;
/// break_events must never be dropped: at least this, and at least the scene's edge count (each
/// edge tears at most once between resets, so no burst can be longer).
constexpr std::uint32_t kBreakQueue = 10000;
constexpr std::uint32_t kStateQueue = 10;
constexpr std::uint32_t kInputQueue = 100;

constexpr std::size_t kNumReasons = static_cast<std::size_t>(RefusalReason::kCount);

/// Monotonic wall time [s].
double wallSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// `value` when it is a number in [min, max]; otherwise warns that live tuning refused it and
/// returns `current`.
double tunedOrKept(const char* name, double value, double min, double max, double current) {
  if (std::isfinite(value) && value >= min && value <= max) {
    return value;
  }
  ROS_WARN("dynamic_reconfigure: %s %g refused: must be a number in [%g, %g]; keeping %g", name,
           value, min, max, current);
  return current;
}

}  // namespace

YarnTearingNode::YarnTearingNode(ros::NodeHandle nh, ros::NodeHandle private_nh,
                                 const SimulationConfig& config)
    : config_(config),
      nh_(nh),
      private_nh_(private_nh),
      simulator_(config.parameters, config.yarns, config.fabrics),
      tf_input_(nh, tf_buffer_),
      frames_(tf_buffer_, config.node.frame_id, config.node.frame_timeout,
              config.node.max_extrapolation),
      inputs_(frames_),
      obstacles_(frames_, config.obstacles, simulator_),
      markers_(config.node.frame_id, config.node.marker_width),
      scheduler_(config.parameters.time_step, config.node.real_time_factor, config.node.max_lag),
      stamps_(ros::Time::isSimTime() && config.node.publish_clock),
      publish_schedule_(config.node.publish_rate),
      diagnostics_(nh, private_nh),
      refusal_warnings_(kWarnPeriod, static_cast<std::size_t>(WarningSource::kCount) * kNumReasons),
      wrenches_(private_nh, tf_buffer_, config.node.frame_id),
      obstacle_wrenches_(private_nh),
      break_log_(std::max<std::size_t>(kBreakQueue, simulator_.scene().edges.size())),
      services_(private_nh) {
  states_pub_ = nh_.advertise<YarnStateArray>("yarn_states", kStateQueue);
  if (!simulator_.scene().fabrics.empty()) {
    fabric_states_pub_ = nh_.advertise<FabricStateArray>("fabric_states", kStateQueue);
  }
  const auto edges = static_cast<std::uint32_t>(simulator_.scene().edges.size());
  breaks_pub_ = nh_.advertise<BreakEvent>("break_events", std::max(kBreakQueue, edges));
  markers_pub_ = nh_.advertise<visualization_msgs::MarkerArray>("yarn_markers", kStateQueue);
  materials_pub_ = nh_.advertise<std_msgs::String>("yarn_materials", 1, /*latch=*/true);
  if (config_.node.publish_clock) {
    clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", kStateQueue);
  }
  force_sub_ = nh_.subscribe("applied_force", kInputQueue, &YarnTearingNode::onAppliedForce, this);
  grasp_sub_ = nh_.subscribe("grasp", kInputQueue, &YarnTearingNode::onGrasp, this);
  ros::NodeHandle& service_nh = services_.handle();
  reset_srv_ = service_nh.advertiseService("reset", &YarnTearingNode::onReset, this);
  pause_srv_ = service_nh.advertiseService("set_paused", &YarnTearingNode::onSetPaused, this);
  break_log_srv_ =
      service_nh.advertiseService("get_break_events", &YarnTearingNode::onGetBreakEvents, this);
  step_watch_timer_ =
      service_nh.createWallTimer(ros::WallDuration(kStepWatchPeriod),
                                 [this](const ros::WallTimerEvent& /*event*/) { onStepWatch(); });

  reconfigure_ = std::make_unique<dynamic_reconfigure::Server<YarnTearingConfig>>(
      reconfigure_mutex_, private_nh_);
  reconfigure_->updateConfig(currentTuning());
  reconfigure_->setCallback(
      [this](YarnTearingConfig& tuning, std::uint32_t level) { onReconfigure(tuning, level); });

  std_msgs::String materials;
  materials.data = describeMaterialsYaml(simulator_.scene());
  materials_pub_.publish(materials);
  ROS_INFO(
      "yarn_tearing_node: %zu yarns, %zu fabrics, %zu obstacles, %zu vertices, time_step %g s, "
      "real_time_factor %g%s",
      config_.yarns.size(), config_.fabrics.size(), config_.obstacles.size(),
      simulator_.scene().vertices.size(), config_.parameters.time_step,
      config_.node.real_time_factor,
      config_.node.real_time_factor == 0.0 ? " (as fast as possible)" : "");
}

YarnTearingNode::~YarnTearingNode() {
  if (loop_lock_.owns_lock()) {
    loop_lock_.unlock();  // run() threw: a service callback may be waiting for the mutex
  }
  services_.stop();
}

void YarnTearingNode::run() {
  // A NodeHandle's queue is the global one unless the nodelet set its own (a ros::CallbackQueue).
  auto& queue = dynamic_cast<ros::CallbackQueue&>(*nh_.getCallbackQueue());
  loop_lock_.lock();
  restartPacing();
  restartPublishSchedule();
  keepStatesToResend();  // a long first step re-sends the initial state
  loop_lock_.unlock();
  services_.start();
  while (ros::ok() && !stop_requested_) {
    double mark = wallSeconds();
    queue.callAvailable();  // its callbacks take mutex_ themselves
    loop_lock_.lock();
    mark = recordStage(LoopStage::kCallbacks, mark);
    stepCycle();
    mark = wallSeconds();
    if (!config_.node.publishesInSimulatedTime() && publish_schedule_.due(mark)) {
      publishState();
      mark = recordStage(LoopStage::kPublishing, mark);
    }
    diagnostics_.update(mark, pacingStatus());
    const double idle = idleTimeout();
    const bool waiting = waiting_for_frames_;
    loop_lock_.unlock();
    mark = wallSeconds();
    queue.callAvailable(ros::WallDuration(idle));
    if (waiting || idle <= 0.0) {  // on schedule, the idle wait is not a cost of the loop
      const std::lock_guard<std::unique_lock<std::mutex>> relock(loop_lock_);
      recordStage(waiting ? LoopStage::kFrameWait : LoopStage::kCallbacks, mark);
    }
  }
  services_.stop();
}

double YarnTearingNode::recordStage(LoopStage stage, double since) {
  const double now = wallSeconds();
  diagnostics_.recordStage(stage, now - since);
  return now;
}

PacingStatus YarnTearingNode::pacingStatus() const {
  PacingStatus pacing;
  pacing.simulated_time = simulatedTime();
  pacing.target_real_time_factor = config_.node.real_time_factor;
  pacing.dropped_steps = scheduler_.droppedSteps();
  pacing.paused = paused_;
  pacing.active_forces = inputs_.activeForces();
  pacing.active_grasps = inputs_.activeGrasps();
  pacing.lag = paused_ ? 0.0 : scheduler_.lag(wallSeconds(), simulatedTime());
  pacing.step_in_progress = stepping_ ? wallSeconds() - step_started_ : 0.0;
  return pacing;
}

double YarnTearingNode::idleTimeout() const {
  if (!paused_ && waiting_for_frames_) {
    return kFramePoll;  // tf2's listener fills the buffer from its own thread
  }
  if (!paused_ && (scheduler_.asFastAsPossible() || behind_)) {
    return 0.0;
  }
  if (config_.node.publishesInSimulatedTime()) {
    return kCyclePeriod;
  }
  return std::min(kCyclePeriod, publish_schedule_.secondsUntilDue(wallSeconds()));
}

bool YarnTearingNode::waitForFrames() {
  const ros::Time step_end = stampOf(simulator_.time() + simulator_.parameters().time_step);
  waiting_for_frames_ = false;
  if (!inputs_.outrunsFrames(step_end) && !obstacles_.outrunsFrames(step_end)) {
    frame_wait_start_ = -1.0;
    return false;
  }
  const double now = wallSeconds();
  if (frame_wait_start_ < 0.0) {
    frame_wait_start_ = now;
  }
  waiting_for_frames_ = now - frame_wait_start_ < kFrameWait;
  return waiting_for_frames_;
}

void YarnTearingNode::stepCycle() {
  behind_ = false;
  waiting_for_frames_ = false;
  if (paused_) {
    return;
  }
  const double targets_start = wallSeconds();
  inputs_.beginCycle();
  obstacles_.beginCycle(simulator_);
  const double start = recordStage(LoopStage::kTargets, targets_start);
  if (scheduler_.asFastAsPossible()) {
    do {
      if (waitForFrames() || !stepOnce(1.0)) break;
    } while (wallSeconds() - start < kStepBudget);
  } else {
    const std::uint64_t due = scheduler_.stepsDue(start, simulator_.time());
    for (std::uint64_t k = 1; k <= due; ++k) {
      if (waitForFrames()) break;
      if (!stepOnce(static_cast<double>(k) / static_cast<double>(due))) {
        return;  // a reset or pause came during the step: pacing restarted, nothing is behind
      }
      if (wallSeconds() - start > kStepBudget) {
        break;  // the rest is caught up in the next cycles (or dropped after max_lag)
      }
    }
    // still behind (a step costs more than its share of wall time): the loop must not idle
    behind_ = scheduler_.lag(wallSeconds(), simulator_.time()) >= simulator_.parameters().time_step;
  }
  const double clock_start = wallSeconds();
  publishClock();
  recordStage(LoopStage::kPublishing, clock_start);
}

bool YarnTearingNode::stepOnce(double fraction) {
  double mark = wallSeconds();
  const ros::Time step_end = stampOf(simulator_.time() + simulator_.parameters().time_step);
  inputs_.beforeStep(simulator_, fraction, step_end);
  obstacles_.beforeStep(simulator_, step_end);
  mark = recordStage(LoopStage::kTargets, mark);
  time_before_step_ = simulator_.time();
  step_started_ = mark;
  stepping_ = true;
  loop_lock_.unlock();  // the service thread answers meanwhile, and leaves the simulator alone
  simulator_.step();
  loop_lock_.lock();
  stepping_ = false;
  mark = recordStage(LoopStage::kPhysics, mark);
  diagnostics_.recordStep(simulator_.lastHealth(), simulator_.scene());
  if (!simulator_.lastHealth().restored_yarns.empty()) {
    reportRestoredYarns();
  }
  publishBreakEvents();
  if (config_.node.publishesInSimulatedTime() && publish_schedule_.due(simulator_.time())) {
    publishClock();
    publishState();
  }
  recordStage(LoopStage::kPublishing, mark);
  return !applyPendingRequests();
}

bool YarnTearingNode::applyPendingRequests() {
  const bool pending = reset_pending_ || pause_pending_.has_value();
  if (reset_pending_) {
    reset_pending_ = false;
    resetNow();
  }
  if (pause_pending_) {
    setPaused(*pause_pending_);
    pause_pending_.reset();
    reconfigure_->updateConfig(currentTuning());  // dynamic_reconfigure clients see it
  }
  return pending;
}

void YarnTearingNode::onStepWatch() {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!stepping_) {
    return;  // between steps run() publishes and reports itself
  }
  const double now = wallSeconds();
  // Only once the step has run a whole period: the deadline that fell in its first period is left
  // to run(), which publishes the new state right after the step, so no deadline goes twice.
  const bool long_step = now - step_started_ >= 1.0 / config_.node.publish_rate;
  const bool resendable = last_states_ || last_fabric_states_;
  if (resendable && long_step && !config_.node.publishesInSimulatedTime() &&
      publish_schedule_.due(now)) {
    // The state as of the last step, as while paused: stamp and sim_time unchanged.
    if (last_states_ && states_pub_.getNumSubscribers() > 0) {
      states_pub_.publish(last_states_);
    }
    if (last_fabric_states_ && fabric_states_pub_.getNumSubscribers() > 0) {
      fabric_states_pub_.publish(last_fabric_states_);
    }
  }
  diagnostics_.update(now, pacingStatus());
}

void YarnTearingNode::reportRestoredYarns() {
  const Scene& scene = simulator_.scene();
  std::string names;
  for (std::uint32_t yarn : simulator_.lastHealth().restored_yarns) {
    inputs_.forgetYarn(scene, yarn);
    names += (names.empty() ? "'" : ", '") + clipped(scene.yarns[yarn].name) + "'";
  }
  const std::size_t key = warningKey(WarningSource::kRestoredYarn, 0);
  if (refusal_warnings_.shouldReport(key, wallSeconds())) {
    ROS_ERROR(
        "yarn_tearing_node: a step left non-finite values in yarn %s at t = %.4f s: restored to "
        "its initial state, its forces and grasps cleared (%llu more such steps held back)",
        names.c_str(), simulator_.time(),
        static_cast<unsigned long long>(refusal_warnings_.heldBack(key)));
  }
}

void YarnTearingNode::publishBreakEvents() {
  for (const TearEvent& event : simulator_.takeTearEvents()) {
    BreakEvent msg =
        toBreakEventMsg(event, simulator_.scene(), config_.node.frame_id, stampOf(event.time));
    break_log_.record(msg);
    breaks_pub_.publish(msg);
    markers_.addBreak(event.yarn, event.position);
    if (!msg.fabric.empty()) {
      ROS_INFO(
          "fabric '%s' tore: %s yarn %d, segment %d (vertices %d-%d) at t = %.4f s: tension %.4g "
          "N, stress %.4g Pa, strain %.4g",
          msg.fabric.c_str(), familyName(event.segment.family), msg.fabric_yarn, msg.segment,
          msg.vertex_a, msg.vertex_b, event.time, event.tension, event.stress, event.strain);
      continue;
    }
    ROS_INFO(
        "yarn '%s' tore at edge %d (vertices %d-%d) at t = %.4f s: tension %.4g N, "
        "stress %.4g Pa, strain %.4g",
        msg.yarn.c_str(), msg.edge, msg.vertex_a, msg.vertex_b, event.time, event.tension,
        event.stress, event.strain);
  }
}

void YarnTearingNode::publishState() {
  const ros::Time stamp = stampOf(simulator_.time());
  // What is not built now is not re-sent later: it would be older than what follows it.
  last_states_.reset();
  last_fabric_states_.reset();
  if (states_pub_.getNumSubscribers() > 0) {
    last_states_ = boost::make_shared<const YarnStateArray>(
        toYarnStateArray(simulator_, config_.node.frame_id, stamp));
    states_pub_.publish(last_states_);
  }
  if (fabric_states_pub_ && fabric_states_pub_.getNumSubscribers() > 0) {
    last_fabric_states_ = boost::make_shared<const FabricStateArray>(
        toFabricStateArray(simulator_, config_.node.frame_id, stamp));
    fabric_states_pub_.publish(last_fabric_states_);
  }
  if (markers_pub_.getNumSubscribers() > 0) {
    markers_pub_.publish(buildMarkers(stamp));
  }
  wrenches_.publish(simulator_, inputs_.graspFrames(), stamp);
  publishObstacleWrenches(stamp);
}

void YarnTearingNode::keepStatesToResend() {
  const ros::Time stamp = stampOf(simulator_.time());
  last_states_ = boost::make_shared<const YarnStateArray>(
      toYarnStateArray(simulator_, config_.node.frame_id, stamp));
  if (fabric_states_pub_) {
    last_fabric_states_ = boost::make_shared<const FabricStateArray>(
        toFabricStateArray(simulator_, config_.node.frame_id, stamp));
  }
}

visualization_msgs::MarkerArray YarnTearingNode::buildMarkers(const ros::Time& stamp) {
  visualization_msgs::MarkerArray array = markers_.build(simulator_.scene(), stamp);
  for (std::size_t i = 0; i < obstacles_.size(); ++i) {
    if (const std::optional<std::size_t> index = obstacles_.simulatorIndex(i)) {
      for (visualization_msgs::Marker& marker :
           obstacleMarkers(simulator_.obstacles()[*index], simulator_.contactWrench(*index),
                           config_.node.frame_id, stamp)) {
        array.markers.push_back(std::move(marker));
      }
    }
  }
  return array;
}

void YarnTearingNode::publishObstacleWrenches(const ros::Time& stamp) {
  for (std::size_t i = 0; i < obstacles_.size(); ++i) {
    const std::optional<std::size_t> index = obstacles_.simulatorIndex(i);
    const std::string topic = "obstacles/" + obstacles_.spec(i).obstacle.name + "/wrench";
    if (!index || !obstacle_wrenches_.wanted(topic)) continue;
    const ContactWrench wrench = simulator_.contactWrench(*index);
    if (!wrench.force.allFinite() || !wrench.torque.allFinite()) continue;  // a restored step
    // the core's torque is about the obstacle's origin p: about frame_id's it is tau + p x F
    const Eigen::Vector3d origin = simulator_.obstacles()[*index].pose.translation();
    obstacle_wrenches_.publish(topic, config_.node.frame_id, stamp, wrench.force,
                               wrench.torque + origin.cross(wrench.force));
  }
}

void YarnTearingNode::setPaused(bool paused) {
  if (paused_ && !paused) {
    restartPacing();
  }
  if (paused_ != paused) {
    diagnostics_.restartWindow();
  }
  paused_ = paused;
}

void YarnTearingNode::restartPublishSchedule() {
  publish_schedule_.restart(config_.node.publishesInSimulatedTime() ? simulator_.time()
                                                                    : wallSeconds());
}

YarnTearingConfig YarnTearingNode::currentTuning() const {
  YarnTearingConfig tuning = YarnTearingConfig::__getDefault__();
  tuning.real_time_factor = config_.node.real_time_factor;
  tuning.publish_rate = config_.node.publish_rate;
  tuning.air_damping = simulator_.parameters().air_damping;
  tuning.regularization = simulator_.parameters().regularization;
  tuning.breaking_enabled = simulator_.parameters().breaking_enabled;
  tuning.paused = paused_;
  return tuning;
}

void YarnTearingNode::onReconfigure(YarnTearingConfig& tuning, std::uint32_t /*level*/) {
  const std::lock_guard<std::mutex> lock(mutex_);
  SimulationParameters parameters = simulator_.parameters();
  // The start parameters' checks: a value that is not a number in its range keeps the current one.
  tuning.real_time_factor =
      tunedOrKept("real_time_factor", tuning.real_time_factor, 0.0,
                  parameter_bounds::kMaxRealTimeFactor, config_.node.real_time_factor);
  tuning.publish_rate =
      tunedOrKept("publish_rate", tuning.publish_rate, parameter_bounds::kMinPublishRate,
                  parameter_bounds::kMaxPublishRate, config_.node.publish_rate);
  tuning.regularization = tunedOrKept("regularization", tuning.regularization, 0.0,
                                      std::nextafter(1.0, 0.0), parameters.regularization);
  if (tuning.air_damping < maxStableAirDamping(config_)) {
    parameters.air_damping = tuning.air_damping;
  } else {
    ROS_WARN(
        "dynamic_reconfigure: air_damping %g refused: must be below %g N*s/m^2 (the lightest "
        "yarn's mass per length / time_step); keeping %g",
        tuning.air_damping, maxStableAirDamping(config_), parameters.air_damping);
  }
  parameters.regularization = tuning.regularization;
  parameters.breaking_enabled = tuning.breaking_enabled;
  try {
    simulator_.setParameters(parameters);
  } catch (const std::invalid_argument& e) {
    ROS_WARN("dynamic_reconfigure refused: %s", e.what());
  }
  if (tuning.real_time_factor != config_.node.real_time_factor ||
      tuning.publish_rate != config_.node.publish_rate) {
    config_.node.real_time_factor = tuning.real_time_factor;
    config_.node.publish_rate = tuning.publish_rate;
    scheduler_.setRealTimeFactor(tuning.real_time_factor);
    publish_schedule_ = RateSchedule(tuning.publish_rate);
    restartPacing();
    restartPublishSchedule();
  }
  setPaused(tuning.paused);
  tuning = currentTuning();  // what is in effect goes back to the clients
  ROS_INFO(
      "yarn_tearing_node: real_time_factor %g, publish_rate %g Hz, air_damping %g N*s/m^2, "
      "regularization %g, breaking %s%s",
      tuning.real_time_factor, tuning.publish_rate, tuning.air_damping, tuning.regularization,
      tuning.breaking_enabled ? "enabled" : "disabled", tuning.paused ? ", paused" : "");
}

void YarnTearingNode::restartPacing() {
  const double wall_now = wallSeconds();
  scheduler_.restart(wall_now, simulator_.time());
  stamps_.synchronize(ros::Time::now(), wall_now);
}

ros::Time YarnTearingNode::stampOf(double sim_time) const {
  return stamps_.stamp(sim_time, scheduler_, ros::Time::now());
}

void YarnTearingNode::publishClock() {
  if (!config_.node.publish_clock) {
    return;
  }
  rosgraph_msgs::Clock clock;
  clock.clock = simulatedStamp(simulator_.time());
  clock_pub_.publish(clock);
}

void YarnTearingNode::onAppliedForce(const AppliedForce::ConstPtr& msg) {
  const std::lock_guard<std::mutex> lock(mutex_);
  try {
    inputs_.handleAppliedForce(*msg, simulator_);
  } catch (const InputRejected& e) {
    warnRefused(WarningSource::kAppliedForce, "applied_force", msg->vertex, e);
  } catch (const std::exception& e) {
    warnRefused(WarningSource::kAppliedForce, "applied_force", msg->vertex,
                InputRejected(RefusalReason::kUnexpected, e.what()));
  }
}

void YarnTearingNode::onGrasp(const Grasp::ConstPtr& msg) {
  const std::lock_guard<std::mutex> lock(mutex_);
  try {
    inputs_.handleGrasp(*msg, simulator_);
  } catch (const InputRejected& e) {
    warnRefused(WarningSource::kGrasp, "grasp", msg->vertex, e);
  } catch (const std::exception& e) {
    warnRefused(WarningSource::kGrasp, "grasp", msg->vertex,
                InputRejected(RefusalReason::kUnexpected, e.what()));
  }
}

std::size_t YarnTearingNode::warningKey(WarningSource source, std::size_t reason) {
  return static_cast<std::size_t>(source) * kNumReasons + reason;
}

void YarnTearingNode::warnRefused(WarningSource source, const char* topic, int vertex,
                                  const InputRejected& e) {
  const std::size_t key = warningKey(source, static_cast<std::size_t>(e.reason()));
  if (refusal_warnings_.shouldReport(key, wallSeconds())) {
    ROS_WARN("%s refused (%s, vertex %d; %llu more of this reason held back): %s", topic,
             reasonName(e.reason()), vertex,
             static_cast<unsigned long long>(refusal_warnings_.heldBack(key)), e.what());
  }
}

bool YarnTearingNode::onReset(std_srvs::Empty::Request& /*request*/,
                              std_srvs::Empty::Response& /*response*/) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (stepping_) {
    reset_pending_ = true;  // applied before a pending pause: a reset keeps the pause state
    return true;
  }
  resetNow();
  return true;
}

void YarnTearingNode::resetNow() {
  simulator_.reset();
  inputs_.clear();
  markers_.clearBreaks();
  break_log_.clear();
  restartPacing();
  keepStatesToResend();  // never re-send a state from before the reset
  // A reset never publishes at once: however many resets come, states keep publish_rate (in wall
  // time the schedule simply goes on; in simulated time it starts one period after time 0).
  if (config_.node.publishesInSimulatedTime()) {
    publish_schedule_.restartAfterPeriod(simulator_.time());
  }
  diagnostics_.restartWindow();
  ROS_INFO("yarn_tearing_node: reset");
}

bool YarnTearingNode::onGetBreakEvents(GetBreakEvents::Request& request,
                                       GetBreakEvents::Response& response) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (reset_pending_) {  // answered as after the reset, which the caller may have had answered
    response.first = request.first;
    response.total = 0;
    return true;
  }
  response.events = break_log_.since(request.first);
  response.first = std::max(request.first, break_log_.oldest());
  response.total = break_log_.total();
  return true;
}

bool YarnTearingNode::onSetPaused(std_srvs::SetBool::Request& request,
                                  std_srvs::SetBool::Response& response) {
  std::unique_lock<std::mutex> lock(mutex_);
  response.success = true;
  response.message = request.data ? "paused" : "running";
  if (stepping_) {
    pause_pending_ = request.data;  // from the end of the step under way
    return true;
  }
  setPaused(request.data);
  const YarnTearingConfig tuning = currentTuning();
  lock.unlock();  // the reconfigure server's mutex is taken after mutex_ only by run()'s thread
  reconfigure_->updateConfig(tuning);  // dynamic_reconfigure clients see it
  return true;
}

}  // namespace ros_layer
}  // namespace yarn_tearing
