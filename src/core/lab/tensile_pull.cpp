#include "yarn_tearing/core/lab/tensile_pull.hpp"

#include <cmath>
#include <stdexcept>

#include "yarn_tearing/core/simulation/simulator.hpp"

namespace yarn_tearing {

TensilePullResult pullSpecimen(YarnSpec spec, const TensilePullSettings& settings) {
  if (!(std::isfinite(settings.extension_rate) && settings.extension_rate > 0.0) ||
      !(settings.record_interval >= 0.0) || !(settings.max_strain >= 0.0)) {
    throw std::invalid_argument(
        "tensile pull: extension_rate must be > 0 [1/s], record_interval and max_strain >= 0");
  }
  spec.pinned = {0};
  spec.end_mass = 0.0;
  SimulationParameters parameters;
  parameters.time_step = settings.time_step;
  parameters.gravity.setZero();
  Simulator sim(parameters, {spec});

  const StressStrainCurve& curve = spec.material.curve;
  const double rate = settings.extension_rate;
  const double max_strain =
      settings.max_strain > 0.0 ? settings.max_strain : 4.0 * curve.breakingStrain();
  const double interval = settings.record_interval > 0.0 ? settings.record_interval
                                                         : curve.breakingStrain() / rate / 200.0;
  const Eigen::Vector3d axis = spec.direction.normalized();
  const std::uint32_t clamp = sim.scene().globalVertex(0, -1);
  const Eigen::Vector3d start = sim.scene().vertices.position[clamp];

  TensilePullResult result;
  TensileSample latest;  // the load cell in the last step, recorded or not
  double next_record = 0.0;
  while (rate * sim.time() < max_strain) {
    const double t = sim.time() + settings.time_step;
    sim.setKinematicTarget(clamp, start + axis * (rate * spec.length * t));
    sim.step();
    const std::vector<TearEvent> events = sim.takeTearEvents();
    if (!events.empty()) {
      result.torn = true;
      result.breaking_force = events.front().tension;
      result.elongation_at_break = rate * events.front().time;
      result.torn_edge = events.front().edge;
      if (result.trace.empty() || result.trace.back().elongation < latest.elongation) {
        result.trace.push_back(latest);
      }
      result.trace.push_back({result.elongation_at_break, result.breaking_force});
      break;
    }
    latest = {rate * sim.time(), sim.supportForce(0).dot(axis)};
    if (sim.time() >= next_record) {
      result.trace.push_back(latest);
      next_record += interval;
    }
  }
  return result;
}

}  // namespace yarn_tearing
