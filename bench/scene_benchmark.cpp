// The scenes a robot creates beside the benchmarks of step_benchmark.cpp and
// fabric_benchmark.cpp, each with its reference in the same run:
//   BM_FabricHeldAtCorners/N vs BM_FabricAtRest/N: an N x N plain weave held at its two top
//     corners, settled, against the same weave hanging from its whole first row.
//   BM_FabricCornersDrawnApart/16 vs BM_FabricAtRest/16: the node's fabric_draw scene from its
//     first tear on (the tearing and the torn patch flapping from its corners), without air;
//     BM_FabricCornersDrawnApartInAir/16 the same in air (air_damping of config/fabric.yaml).
//   BM_FabricCornersDrawnTaut/16 vs BM_FabricAtRest/16: the same scene drawn, before its first
//     tear.
//   BM_FabricCornersSwinging/N vs BM_FabricAtRest/N: the same scene before it is drawn, the patch
//     swinging down from its corners.
//   BM_PatchObstacle/K: a 16 x 12 cotton patch hanging from its first row; K = 0 without an
//     obstacle (the reference), 1 a 3 cm ball pressed 1 mm into its middle from the front (its
//     cap, 11 mm across in the patch's plane, pokes through a 12.5 mm cell: the patch hangs
//     beside it, within the contact margin), 2 the ball pressed 4 mm in (its cap wider than a
//     cell: the patch drapes over it, held off by its contacts). A solid placed through the
//     patch is refused (deep_overlap_test.cpp).
//   BM_DiagonalGrid/8/D: an 8 x 8 cotton grid along rows and columns, top row pinned, 0.1 N down
//     on each vertex of its bottom row, built as a Scene; D = 1 adds both diagonals of every cell
//     (more edges than vertices, q > n), D = 0 is the reference without them.
// Run: build/core/yarn_tearing_bench --benchmark_filter='HeldAtCorners|FabricAtRest|Patch|Diagonal'
//        --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "bench_support.hpp"
#include "yarn_tearing/core/simulation/simulator.hpp"

namespace yarn_tearing {
namespace {

/// Steps `sim` for `seconds` of simulated time.
void settle(Simulator& sim, double seconds) {
  while (sim.time() < seconds) sim.step();
}

/// range(0) x range(0) vertices, 12.5 mm between yarns (as BM_FabricAtRest), pinned at its two top
/// corners, air damping 0.05 N s/m^2, after 0.5 s: the weave sags between the corners, its top
/// yarns taut, and its weight hangs on them.
void BM_FabricHeldAtCorners(benchmark::State& state) {
  const int side = static_cast<int>(state.range(0));
  FabricSpec spec = plainWeave(side, side, 0.0125);
  spec.pinned = {{0, 0}, {0, -1}};
  SimulationParameters parameters;
  parameters.air_damping = 0.05;
  Simulator sim(parameters, {}, {spec});
  settle(sim, 0.5);
  timeSteps(state, sim);
}

/// The scene of tools/measure_fabric_draw.py: a `side` x `side` cotton patch, 8 x 8 cm, 2 %
/// crimp, pinned at its two top corners, which from 0.3 s on are drawn apart along the weft at
/// 2 cm/s each (drive()); `air_damping` [N s/m^2] as SimulationParameters::air_damping.
class CornersDrawnApart {
 public:
  explicit CornersDrawnApart(int side, double air_damping = 0.0)
      : sim_(parameters(air_damping), {}, {patch(side)}) {
    left_ = sim_.scene().fabricVertex(0, 0, 0);
    right_ = sim_.scene().fabricVertex(0, 0, -1);
    left_start_ = sim_.scene().vertices.position[left_];
    right_start_ = sim_.scene().vertices.position[right_];
  }
  /// The scene at its start (flat, at rest).
  Simulator& start() { return sim_; }
  /// Sets the corners' targets for the next step of `sim` and steps it.
  void drive(Simulator& sim) const {
    const double travel =
        kDrawSpeed * std::max(sim.time() + sim.parameters().time_step - kDrawStart, 0.0);
    if (travel > 0.0) {
      sim.setKinematicTarget(left_, left_start_ - Eigen::Vector3d(travel, 0.0, 0.0));
      sim.setKinematicTarget(right_, right_start_ + Eigen::Vector3d(travel, 0.0, 0.0));
    }
    sim.step();
  }
  static constexpr double kDrawStart = 0.3;   ///< when the corners start moving [s]
  static constexpr double kDrawSpeed = 0.02;  ///< each corner's speed [m/s]

 private:
  static SimulationParameters parameters(double air_damping) {
    SimulationParameters parameters;
    parameters.air_damping = air_damping;
    return parameters;
  }
  static FabricSpec patch(int side) {
    FabricSpec spec = plainWeave(side, side, 0.08 / (side - 1));
    spec.warp_crimp = 0.02;
    spec.weft_crimp = 0.02;
    spec.pinned = {{0, 0}, {0, -1}};
    return spec;
  }
  Simulator sim_;
  std::uint32_t left_ = 0;
  std::uint32_t right_ = 0;
  Eigen::Vector3d left_start_;
  Eigen::Vector3d right_start_;
};

/// The air damping of config/fabric.yaml [N s/m^2].
constexpr double kFabricAirDamping = 1.0e-3;

/// CornersDrawnApart of range(0) x range(0) from its first tear: each iteration steps that
/// state kWindow times, 0.6 s (copying it is not timed): the tearing and the torn patch flapping
/// from its corners. Reference: BM_FabricAtRest/16.
void BM_FabricCornersDrawnApart(benchmark::State& state) {
  constexpr int kWindow = 600;
  CornersDrawnApart scene(static_cast<int>(state.range(0)));
  timeWindowFromFirstTear(state, scene.start(), 3.0, kWindow,
                          [&scene](Simulator& sim) { scene.drive(sim); });
}

/// BM_FabricCornersDrawnApart in air: air_damping 1e-3 N s/m^2, as config/fabric.yaml and the
/// fabric demo (about a woven sheet's drag at 0.5 m/s shared over its yarns, doc/performance.md).
/// Reference: BM_FabricAtRest/16.
void BM_FabricCornersDrawnApartInAir(benchmark::State& state) {
  constexpr int kWindow = 600;
  CornersDrawnApart scene(static_cast<int>(state.range(0)), kFabricAirDamping);
  timeWindowFromFirstTear(state, scene.start(), 3.0, kWindow,
                          [&scene](Simulator& sim) { scene.drive(sim); });
}

/// CornersDrawnApart of range(0) x range(0) while drawn, before it tears: from 0.3 s, when the
/// corners start moving, each iteration steps kWindow times, to 0.47 s (its first tear comes at
/// 0.485 s): the phase the node's fabric_draw measures as "drawn before the first tear".
/// Reference: BM_FabricAtRest of the same size.
void BM_FabricCornersDrawnTaut(benchmark::State& state) {
  constexpr int kWindow = 170;
  CornersDrawnApart scene(static_cast<int>(state.range(0)));
  const auto drawn = [](const Simulator& sim) {
    return sim.time() >= CornersDrawnApart::kDrawStart - 1e-9;
  };
  timeWindowFrom(state, scene.start(), drawn, kWindow,
                 [&scene](Simulator& sim) { scene.drive(sim); });
}

/// CornersDrawnApart of range(0) x range(0) before it is drawn: from 0.1 s, each iteration steps
/// kWindow times, to 0.3 s: the patch let go flat, swinging down from its corners. Reference:
/// BM_FabricAtRest of the same size.
void BM_FabricCornersSwinging(benchmark::State& state) {
  constexpr int kWindow = 200;
  CornersDrawnApart scene(static_cast<int>(state.range(0)));
  const auto swinging = [](const Simulator& sim) { return sim.time() >= 0.1 - 1e-9; };
  timeWindowFrom(state, scene.start(), swinging, kWindow,
                 [&scene](Simulator& sim) { scene.drive(sim); });
}

/// The 16 x 12 patch (12.5 mm between yarns, pinned along its first row, air damping) settled for
/// 0.2 s, then the obstacle of range(0) set and the first 0.05 s stepped before timing.
void BM_PatchObstacle(benchmark::State& state) {
  FabricSpec spec = plainWeave(16, 12, 0.0125);
  spec.pinned_sides = {FabricSide::kFirstRow};
  SimulationParameters parameters;
  parameters.air_damping = 0.05;
  Simulator sim(parameters, {}, {spec});
  settle(sim, 0.2);
  const Scene& scene = sim.scene();
  const Eigen::Vector3d middle = 0.5 * (scene.vertices.position[scene.fabricVertex(0, 0, 0)] +
                                        scene.vertices.position[scene.fabricVertex(0, -1, -1)]);
  Obstacle o;
  o.name = "obstacle";
  if (state.range(0) == 1) {
    o.shape = ObstacleShape::kSphere;
    o.radius = 0.015;
    // Touching the patch's middle from the front, pressed 1 mm in.
    o.pose.translation() = middle + Eigen::Vector3d(0.0, o.radius - 1.0e-3, 0.0);
  } else if (state.range(0) == 2) {
    o.shape = ObstacleShape::kSphere;
    o.radius = 0.015;
    o.pose.translation() = middle + Eigen::Vector3d(0.0, o.radius - 4.0e-3, 0.0);
  }
  if (state.range(0) != 0) sim.setObstacles({o});
  settle(sim, 0.25);
  timeSteps(state, sim);
}

/// The 8 x 8 grid (12.5 mm, the cotton yarn's mass per vertex as BM_GridAtRest), with both
/// diagonals of every cell when range(1) = 1, after 0.2 s with air damping.
void BM_DiagonalGrid(benchmark::State& state) {
  const int side = static_cast<int>(state.range(0));
  const bool diagonals = state.range(1) != 0;
  const double spacing = 0.0125;
  const double radius = 1.0e-4;
  const double area = M_PI * radius * radius;
  Scene scene;
  Yarn yarn;
  yarn.name = "grid";
  yarn.material.curve = cotton();
  yarn.radius = radius;
  yarn.num_vertices = static_cast<std::uint32_t>(side * side);
  scene.yarns.push_back(yarn);
  const double vertex_mass = 2.0 * yarn.material.density * area * spacing;
  auto id = [side](int row, int col) { return static_cast<std::uint32_t>(row * side + col); };
  for (int row = 0; row < side; ++row) {
    for (int col = 0; col < side; ++col) {
      scene.vertices.add(Eigen::Vector3d(col * spacing, 0.0, -row * spacing), vertex_mass,
                         2.0 * spacing, 0);
      if (row == 0) scene.vertices.motion.back() = VertexMotion::kPinned;
      if (row == side - 1) scene.vertices.applied_force.back() = Eigen::Vector3d(0.0, 0.0, -0.1);
    }
  }
  const double diagonal = std::sqrt(2.0) * spacing;
  for (int row = 0; row < side; ++row) {
    for (int col = 0; col < side; ++col) {
      if (col + 1 < side) scene.edges.add(id(row, col), id(row, col + 1), 0, spacing, area, 1.0);
      if (row + 1 < side) scene.edges.add(id(row, col), id(row + 1, col), 0, spacing, area, 1.0);
      if (diagonals && row + 1 < side && col + 1 < side) {
        scene.edges.add(id(row, col), id(row + 1, col + 1), 0, diagonal, area, 1.0);
        scene.edges.add(id(row, col + 1), id(row + 1, col), 0, diagonal, area, 1.0);
      }
    }
  }
  scene.yarns[0].num_edges = static_cast<std::uint32_t>(scene.edges.size());
  SimulationParameters parameters;
  parameters.air_damping = 0.05;
  Simulator sim(parameters, scene);
  settle(sim, 0.2);
  timeSteps(state, sim);
}

BENCHMARK(BM_FabricHeldAtCorners)->Arg(32)->Arg(64)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FabricCornersDrawnApart)->Arg(16)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_FabricCornersDrawnApartInAir)
    ->Arg(16)
    ->Arg(32)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_FabricCornersDrawnTaut)->Arg(16)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_FabricCornersSwinging)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_PatchObstacle)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DiagonalGrid)->Args({8, 0})->Args({8, 1})->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace yarn_tearing
