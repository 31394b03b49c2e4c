// /diagnostics says ERROR at once, naming the yarn, when a step restored a yarn from a non-finite
// state (SimulationDiagnostics), even with a long ~diagnostic_period; the next report is OK again.
// No input can produce a non-finite step (every bound is checked first), so the step's health is
// handed over directly, as YarnTearingNode does after each step.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <string>
#include <vector>

#include "yarn_tearing/core/model/scene.hpp"
#include "yarn_tearing/core/simulation/step_health.hpp"
#include "yarn_tearing/ros/simulation_diagnostics.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

constexpr double kPeriod = 30.0;  ///< [s] ~diagnostic_period: far longer than the test waits
constexpr double kWait = 5.0;     ///< [s, wall] for a message to arrive

Scene sceneWithYarn(const std::string& name) {
  YarnSpec spec;
  spec.name = name;
  spec.material.name = "fibre";
  spec.material.density = 1500.0;
  spec.material.curve = StressStrainCurve({{0.0, 0.0}, {0.01, 1.0e8}, {0.05, 3.0e8}});
  spec.radius = 1.0e-4;
  spec.length = 0.2;
  spec.num_vertices = 5;
  return buildScene({spec});
}

class DiagnosticsListener {
 public:
  explicit DiagnosticsListener(ros::NodeHandle& nh)
      : subscriber_(nh.subscribe("/diagnostics", 10, &DiagnosticsListener::receive, this)) {}
  /// Waits until a status arrives (spinning); false after kWait.
  bool waitForStatus(diagnostic_msgs::DiagnosticStatus& status) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(kWait);
    while (received_.empty() && ros::WallTime::now() < deadline) {
      ros::spinOnce();
      ros::WallDuration(0.01).sleep();
    }
    if (received_.empty()) return false;
    status = received_.front();
    received_.erase(received_.begin());
    return true;
  }
  bool connected() const { return subscriber_.getNumPublishers() > 0; }

 private:
  void receive(const diagnostic_msgs::DiagnosticArray& array) {
    received_.insert(received_.end(), array.status.begin(), array.status.end());
  }
  ros::Subscriber subscriber_;
  std::vector<diagnostic_msgs::DiagnosticStatus> received_;
};

TEST(DiagnosticsError, RestoredYarnIsReportedAsErrorAtOnce) {
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  private_nh.setParam("diagnostic_period", kPeriod);
  SimulationDiagnostics diagnostics(nh, private_nh);
  DiagnosticsListener listener(nh);
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(kWait);
  while (!listener.connected() && ros::WallTime::now() < deadline) {
    ros::WallDuration(0.01).sleep();
  }
  ASSERT_TRUE(listener.connected());

  const Scene scene = sceneWithYarn("frayed_yarn");
  PacingStatus pacing;
  pacing.target_real_time_factor = 1.0;
  double wall = 100.0;  // [s] the node's monotonic clock; its origin does not matter
  StepHealth healthy;
  diagnostics.recordStep(healthy, scene);
  diagnostics.update(wall, pacing);  // the first update starts the period with a report
  diagnostic_msgs::DiagnosticStatus status;
  ASSERT_TRUE(listener.waitForStatus(status)) << "no first report within " << kWait << " s";
  EXPECT_EQ(status.level, diagnostic_msgs::DiagnosticStatus::OK) << status.message;
  StepHealth restored;
  restored.restored_yarns = {0};
  diagnostics.recordStep(restored, scene);
  wall += 0.001;
  pacing.simulated_time = 0.001;
  diagnostics.update(wall, pacing);  // 1 ms into a 30 s period

  ASSERT_TRUE(listener.waitForStatus(status)) << "no report within " << kWait << " s";
  EXPECT_EQ(status.level, diagnostic_msgs::DiagnosticStatus::ERROR);
  EXPECT_NE(status.message.find("frayed_yarn"), std::string::npos) << status.message;
  bool counted = false;
  for (const diagnostic_msgs::KeyValue& entry : status.values) {
    if (entry.key == "yarns restored from a non-finite state") counted = entry.value == "1";
  }
  EXPECT_TRUE(counted);

  // The next period's report, after healthy steps only, is OK again.
  diagnostics.recordStep(healthy, scene);
  wall += kPeriod;
  pacing.simulated_time = kPeriod;
  diagnostics.update(wall, pacing);
  ASSERT_TRUE(listener.waitForStatus(status));
  EXPECT_EQ(status.level, diagnostic_msgs::DiagnosticStatus::OK) << status.message;
}

}  // namespace
}  // namespace ros_layer
}  // namespace yarn_tearing

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "diagnostics_error_test");
  return RUN_ALL_TESTS();
}
