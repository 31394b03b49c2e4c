// The projection and the tension solver on a general edge graph (vertices with many edges, more
// edges than vertices), as a woven patch will need.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "test_support.hpp"
#include "yarn_tearing/core/projection/edge_gram_solver.hpp"

namespace yarn_tearing::test {
namespace {

/// A square patch of `side` x `side` vertices with structural and both shear diagonals, hanging
/// from its pinned top row. Edges outnumber vertices.
Scene hangingPatch(int side, double spacing) {
  Scene scene;
  Yarn yarn;
  yarn.name = "patch";
  yarn.material = cottonLike();
  yarn.radius = 1.0e-4;
  yarn.num_vertices = static_cast<std::uint32_t>(side * side);
  scene.yarns.push_back(yarn);
  const double area = kPi * 1.0e-8;
  const double vertex_mass = 1520.0 * area * spacing * 2.0;
  auto id = [side](int row, int col) { return static_cast<std::uint32_t>(row * side + col); };
  for (int row = 0; row < side; ++row) {
    for (int col = 0; col < side; ++col) {
      scene.vertices.add(Eigen::Vector3d(col * spacing, 0.0, -row * spacing), vertex_mass, spacing,
                         0);
      if (row == 0) scene.vertices.motion.back() = VertexMotion::kPinned;
    }
  }
  auto link = [&](std::uint32_t a, std::uint32_t b) {
    const double rest = (scene.vertices.position[a] - scene.vertices.position[b]).norm();
    scene.edges.add(a, b, 0, rest, area, 1.0);
  };
  for (int row = 0; row < side; ++row) {
    for (int col = 0; col < side; ++col) {
      if (col + 1 < side) link(id(row, col), id(row, col + 1));
      if (row + 1 < side) link(id(row, col), id(row + 1, col));
      if (row + 1 < side && col + 1 < side) link(id(row, col), id(row + 1, col + 1));
      if (row + 1 < side && col > 0) link(id(row, col), id(row + 1, col - 1));
    }
  }
  scene.yarns[0].num_edges = static_cast<std::uint32_t>(scene.edges.size());
  return scene;
}

TEST(EdgeGraph, GeneralSolverMatchesADenseSolve) {
  Scene scene = hangingPatch(4, 0.01);
  const std::size_t q = scene.edges.size();
  ASSERT_GT(q, scene.vertices.size());
  EdgeGramSolver solver;
  solver.setTopology(scene.edges, scene.vertices.size());
  EXPECT_FALSE(solver.usesBandedPath());

  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uniform(0.5, 2.0);
  std::vector<Eigen::Vector3d> direction(q);
  for (std::size_t e = 0; e < q; ++e) {
    const Eigen::Vector3d d = scene.vertices.position[scene.edges.vertex_b[e]] -
                              scene.vertices.position[scene.edges.vertex_a[e]];
    direction[e] = d.normalized();
  }
  std::vector<double> weight(scene.vertices.size());
  for (double& w : weight) w = uniform(rng);
  std::vector<std::uint8_t> active(q, 1);
  active[3] = 0;
  std::vector<double> shift(q, 0.1);
  std::vector<double> rhs(q);
  for (double& r : rhs) r = uniform(rng);
  const std::vector<double> original = rhs;

  // Dense G = J W J^T + diag(shift), built from its definition.
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(q, 3 * scene.vertices.size());
  for (std::size_t e = 0; e < q; ++e) {
    if (!active[e]) continue;
    jacobian.block<1, 3>(e, 3 * scene.edges.vertex_a[e]) = -direction[e].transpose();
    jacobian.block<1, 3>(e, 3 * scene.edges.vertex_b[e]) = direction[e].transpose();
  }
  Eigen::VectorXd w3(3 * scene.vertices.size());
  for (std::size_t v = 0; v < scene.vertices.size(); ++v)
    w3.segment<3>(3 * v).setConstant(weight[v]);
  Eigen::MatrixXd dense = jacobian * w3.asDiagonal() * jacobian.transpose();
  Eigen::VectorXd b = Eigen::Map<const Eigen::VectorXd>(original.data(), q);
  for (std::size_t e = 0; e < q; ++e) {
    if (active[e]) {
      dense(e, e) += shift[e];
    } else {
      dense(e, e) = 1.0;
      b[e] = 0.0;
    }
  }
  const Eigen::VectorXd expected = dense.ldlt().solve(b);

  GramSystem system;
  system.direction = &direction;
  system.vertex_weight = &weight;
  system.active = &active;
  system.diagonal_shift = &shift;
  solver.solve(scene.edges, system, rhs);
  for (std::size_t e = 0; e < q; ++e) EXPECT_NEAR(rhs[e], expected[e], 1e-12) << "edge " << e;
}

TEST(EdgeGraph, HangingPatchSupportsCarryItsWeight) {
  SimulationParameters p;
  p.air_damping = 0.05;
  Simulator sim(p, hangingPatch(6, 0.01));
  for (int i = 0; i < 2000; ++i) sim.step();
  EXPECT_TRUE(sim.lastHealth().projection_converged);
  EXPECT_LE(sim.lastHealth().max_constraint_violation, p.constraint_tolerance);

  const VertexSet& v = sim.scene().vertices;
  double weight = 0.0;
  Eigen::Vector3d support = Eigen::Vector3d::Zero();
  for (std::uint32_t i = 0; i < v.size(); ++i) {
    weight += v.mass[i] * kGravity;
    support += sim.supportForce(i);
  }
  EXPECT_NEAR(-support.z(), weight, 0.005 * weight);
  EXPECT_NEAR(support.x(), 0.0, 0.005 * weight);
}

TEST(EdgeGraph, RejectsAnEdgeToAMissingVertex) {
  Scene scene = hangingPatch(3, 0.01);
  scene.edges.vertex_b[0] = 99;
  EXPECT_THROW(Simulator(SimulationParameters{}, scene), std::invalid_argument);
}

TEST(PaperVelocityRows, HangingYarnTensionEqualsWeightBelow) {
  SimulationParameters p;
  p.air_damping = 0.05;
  p.tension_rows = TensionRowWeighting::kVelocity;
  Simulator sim(p, {hangingYarn()});
  for (int i = 0; i < 3000; ++i) sim.step();
  const Scene& s = sim.scene();
  for (std::size_t e = 0; e < s.edges.size(); ++e) {
    double mass_below = 0.0;
    for (std::size_t v = s.edges.vertex_b[e]; v < s.vertices.size(); ++v)
      mass_below += s.vertices.mass[v];
    EXPECT_NEAR(s.edges.tension[e], mass_below * kGravity, 0.005 * mass_below * kGravity);
  }
}

/// Health of the last step of a hanging yarn (0.3 s, end weight `end_mass` [kg]) needed.
StepHealth settledHealth(ProjectionMethod method, double end_mass) {
  SimulationParameters p;
  p.projection_method = method;
  p.max_projection_iterations = 5000;
  p.recoil_substeps = 1;  // the method's own solve: no step taken again in substeps
  YarnSpec spec = hangingYarn();
  spec.end_mass = end_mass;
  Simulator sim(p, {spec});
  for (int i = 0; i < 300; ++i) sim.step();
  return sim.lastHealth();
}

TEST(GaussSeidel, ConvergesOnAUniformYarnButNotUnderAHeavyWeight) {
  EXPECT_TRUE(settledHealth(ProjectionMethod::kGaussSeidel, 0.0).projection_converged);
  // 10 g on 0.6 mg vertices: Gauss-Seidel stalls within 5000 sweeps, fast projection does not.
  EXPECT_FALSE(settledHealth(ProjectionMethod::kGaussSeidel, 0.01).projection_converged);
  const StepHealth fast = settledHealth(ProjectionMethod::kFastProjection, 0.01);
  EXPECT_TRUE(fast.projection_converged);
  EXPECT_LE(fast.projection_iterations, 5);
}

}  // namespace
}  // namespace yarn_tearing::test
