// The reference for a hanging fabric's step from another simulator: Bullet's soft-body patch (its
// position-based links, double precision), the same size, spacing, mass and pinned row as
// BM_FabricAtRest. Built when Debian's libbullet-dev is installed.
// Run: build/core/yarn_tearing_bench --benchmark_filter='BM_FabricAtRest/64$|BM_BulletPatchAtRest'
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletSoftBody/btSoftBodyHelpers.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <memory>

#include "bench_support.hpp"
#include "yarn_tearing/core/simulation/simulator.hpp"

namespace yarn_tearing {
namespace {

btVector3 toBullet(const Eigen::Vector3d& x) { return btVector3(x.x(), x.y(), x.z()); }

/// Bullet's dynamics world with one soft-body patch in it; owns both.
class BulletPatchWorld {
 public:
  /// The patch spans the corners of `fabric`'s grid, its first row pinned, with the fabric's
  /// mass [kg] spread evenly over its nodes; `iterations` position-solver passes a step [-].
  BulletPatchWorld(const Simulator& fabric, int side, int iterations)
      : dispatcher_(&configuration_),
        world_(&dispatcher_, &broadphase_, &solver_, &configuration_) {
    const Scene& scene = fabric.scene();
    const auto corner = [&scene](int row, int column) {
      return toBullet(scene.vertices.position[scene.fabricVertex(0, row, column)]);
    };
    double mass = 0.0;  // [kg]
    for (double m : scene.vertices.mass) mass += m;
    world_.setGravity(toBullet(fabric.parameters().gravity));
    btSoftBodyWorldInfo& info = world_.getWorldInfo();
    info.m_gravity = world_.getGravity();
    info.m_sparsesdf.Initialize();
    // Rows and columns only, as a plain weave's yarns; no diagonal links.
    patch_.reset(btSoftBodyHelpers::CreatePatch(info, corner(0, 0), corner(0, side - 1),
                                                corner(side - 1, 0), corner(side - 1, side - 1),
                                                side, side, 0, false));
    patch_->m_materials[0]->m_kLST = 1.0;
    patch_->m_cfg.piterations = iterations;
    patch_->setTotalMass(mass);
    for (int column = 0; column < side; ++column) patch_->setMass(column, 0.0);  // the first row
    world_.addSoftBody(patch_.get());
  }
  ~BulletPatchWorld() { world_.removeSoftBody(patch_.get()); }
  BulletPatchWorld(const BulletPatchWorld&) = delete;
  BulletPatchWorld& operator=(const BulletPatchWorld&) = delete;

  /// One step of `time_step` [s], without substeps.
  void step(double time_step) { world_.stepSimulation(time_step, 1, time_step); }

  /// The largest stretch of a link over its rest length [-].
  double maxStrain() const {
    double strain = 0.0;
    for (int i = 0; i < patch_->m_links.size(); ++i) {
      const btSoftBody::Link& link = patch_->m_links[i];
      const double length = (link.m_n[1]->m_x - link.m_n[0]->m_x).length();
      strain = std::max(strain, length / link.m_rl - 1.0);
    }
    return strain;
  }

 private:
  btSoftBodyRigidBodyCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_;
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btSoftRigidDynamicsWorld world_;
  std::unique_ptr<btSoftBody> patch_;
};

/// Bullet's patch in place of BM_FabricAtRest's fabric (range(0) vertices a side, 12.5 mm apart),
/// range(1) solver iterations a step, Δt = 1 ms, after 0.2 s; `max_strain` is its largest link
/// stretch [-], as BM_FabricAtRest's.
void BM_BulletPatchAtRest(benchmark::State& state) {
  const int side = static_cast<int>(state.range(0));
  const Simulator fabric({}, {}, {benchFabric(side, 0.0125)});
  const double time_step = fabric.parameters().time_step;
  BulletPatchWorld bullet(fabric, side, static_cast<int>(state.range(1)));
  for (double t = 0.0; t < 0.2; t += time_step) bullet.step(time_step);
  for (auto _ : state) {
    bullet.step(time_step);
    benchmark::ClobberMemory();
  }
  state.counters["max_strain"] = bullet.maxStrain();
}

BENCHMARK(BM_BulletPatchAtRest)
    ->Args({16, 10})
    ->Args({64, 10})
    ->Args({64, 100})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace yarn_tearing
