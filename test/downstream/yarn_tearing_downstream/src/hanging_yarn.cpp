// Downstream use of yarn_tearing_core: a yarn pinned at its top hangs under gravity for 2 s (air
// damping settles it); the pin must then carry the yarn's whole weight m*g. Prints the pin force
// and exits 0 when it is within 0.5 % of the weight, 1 otherwise.
#include <cmath>
#include <cstdio>

#include "yarn_tearing/core.hpp"

int main() {
  yarn_tearing::YarnSpec yarn;  // defaults: 0.3 m, 25 vertices, r = 0.1 mm, cotton-like
  yarn.name = "downstream";
  yarn.pinned = {0};
  yarn_tearing::SimulationParameters parameters;
  parameters.air_damping = 0.05;  // [N*s/m^2]
  yarn_tearing::Simulator simulator(parameters, {yarn});
  for (int i = 0; i < 2000; ++i) {
    simulator.step();
  }
  const yarn_tearing::VertexSet& vertices = simulator.scene().vertices;
  double mass = 0.0;  // [kg]
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    mass += vertices.mass[v];
  }
  const double weight = mass * std::abs(parameters.gravity.z());  // [N]
  const double pin_force = -simulator.supportForce(0).z();        // [N] pulled down
  const double relative_error = std::abs(pin_force - weight) / weight;
  std::printf("downstream: pin force %.6g N, weight %.6g N, relative error %.2e\n", pin_force,
              weight, relative_error);
  return relative_error <= 5.0e-3 ? 0 : 1;
}
