#include "yarn_tearing/core/lab/trouser_tear.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace yarn_tearing {
namespace {

/// Mean and sample standard deviation of the peaks.
void summarize(TrouserTearResult& result) {
  const std::vector<double>& peaks = result.peaks;
  if (peaks.empty()) return;
  double sum = 0.0;
  for (const double p : peaks) sum += p;
  result.mean_peak = sum / static_cast<double>(peaks.size());
  if (peaks.size() < 2) return;
  double squares = 0.0;
  for (const double p : peaks) squares += (p - result.mean_peak) * (p - result.mean_peak);
  result.peak_spread = std::sqrt(squares / static_cast<double>(peaks.size() - 1));
}

}  // namespace

TrouserTearResult runTrouserTear(const SimulationParameters& parameters, const FabricSpec& spec,
                                 const TrouserTearSetup& setup,
                                 const std::function<void(const Simulator&)>& observe) {
  spec.validate();
  if (!(setup.slit_rows >= 1 && setup.slit_rows < spec.picks)) {
    throw std::invalid_argument("trouser tear: slit_rows must be in [1, picks)");
  }
  if (!(setup.speed > 0.0 && std::isfinite(setup.speed))) {
    throw std::invalid_argument("trouser tear: speed must be a finite number > 0 [m/s]");
  }
  if (!(setup.duration > 0.0 && std::isfinite(setup.duration))) {
    throw std::invalid_argument("trouser tear: duration must be a finite number > 0 [s]");
  }
  FabricSpec cut = spec;
  const int middle = spec.ends / 2 - 1;  // the weft segment between the tongues
  cut.pinned = {};
  cut.pinned_sides = {FabricSide::kFirstRow};
  cut.slits = {{FabricFamily::kWeft, spec.picks - setup.slit_rows, spec.picks - 1, middle}};
  Simulator sim(parameters, {}, {cut});
  const Scene& scene = sim.scene();
  std::vector<std::uint32_t> grip;
  std::vector<Eigen::Vector3d> start;
  std::vector<double> side;
  for (int c = 0; c < spec.ends; ++c) {
    grip.push_back(scene.fabricVertex(0, -1, c));
    start.push_back(scene.vertices.position[grip.back()]);
    side.push_back(c <= middle ? -1.0 : 1.0);
  }
  const Eigen::Vector3d weft = spec.weft_direction.normalized();
  const double dt = parameters.time_step;
  const int steps = static_cast<int>(std::lround(setup.duration / dt));
  TrouserTearResult result;
  double peak = 0.0;
  bool loading = false;  // a step without a tear since the last tear
  for (int i = 1; i <= steps; ++i) {
    const double travel = setup.speed * i * dt;
    for (std::size_t k = 0; k < grip.size(); ++k) {
      sim.setKinematicTarget(grip[k], start[k] + side[k] * travel * weft);
    }
    sim.step();
    // The fabric pulls each grip back towards the other tongue: -side * support force.
    double force = 0.0;
    for (std::size_t k = 0; k < grip.size(); ++k) {
      force -= side[k] * weft.dot(sim.supportForce(grip[k]));
    }
    result.curve.push_back({2.0 * travel, 0.5 * force});
    std::vector<TearEvent> events = sim.takeTearEvents();
    if (events.empty()) {
      peak = std::max(peak, 0.5 * force);
      loading = true;
    } else {
      if (loading) result.peaks.push_back(peak);
      peak = 0.0;
      loading = false;
      result.events.insert(result.events.end(), events.begin(), events.end());
    }
    if (observe) observe(sim);
  }
  summarize(result);
  return result;
}

}  // namespace yarn_tearing
