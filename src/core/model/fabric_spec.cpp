#include "yarn_tearing/core/model/fabric_spec.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace yarn_tearing {
namespace {

void requireFabric(bool ok, const std::string& fabric, const std::string& what) {
  if (!ok) throw std::invalid_argument("fabric '" + fabric + "': " + what);
}

/// The part of a YarnSpec a fabric uses (material, size, scatter), checked as a yarn's.
void validateYarn(const YarnSpec& yarn, const std::string& fabric, const char* family) {
  YarnSpec checked = yarn;
  checked.name = fabric + "/" + family;
  checked.length = 1.0;
  checked.num_vertices = 2;
  checked.pinned.clear();
  checked.end_mass = 0.0;
  checked.start.setZero();
  checked.direction = Eigen::Vector3d::UnitX();
  try {
    checked.validate();
  } catch (const std::invalid_argument& e) {
    requireFabric(false, fabric, std::string(family) + ": " + e.what());
  }
}

std::string range(int count) {
  return "[" + std::to_string(-count) + ", " + std::to_string(count - 1) + "]";
}

}  // namespace

int FabricSpec::segmentsPerYarn(FabricFamily family) const {
  return family == FabricFamily::kWarp ? picks - 1 : ends - 1;
}

int FabricSpec::yarnCount(FabricFamily family) const {
  return family == FabricFamily::kWarp ? ends : picks;
}

void FabricSpec::validate() const {
  requireFabric(!name.empty(), name, "name must not be empty");
  requireFabric(std::isfinite(warp_length) && warp_length > 0.0, name,
                "warp_length must be > 0 [m]");
  requireFabric(std::isfinite(weft_length) && weft_length > 0.0, name,
                "weft_length must be > 0 [m]");
  requireFabric(ends >= 2, name, "ends must be >= 2, got " + std::to_string(ends));
  requireFabric(picks >= 2, name, "picks must be >= 2, got " + std::to_string(picks));
  requireFabric(origin.allFinite(), name, "origin must be finite [m]");
  requireFabric(warp_direction.allFinite() && warp_direction.norm() > 0.0, name,
                "warp_direction must be a finite non-zero vector");
  requireFabric(weft_direction.allFinite() && weft_direction.norm() > 0.0, name,
                "weft_direction must be a finite non-zero vector");
  const double cosine = warp_direction.normalized().dot(weft_direction.normalized());
  requireFabric(std::abs(cosine) < 0.99, name,
                "warp_direction and weft_direction must not be parallel");
  validateYarn(warp, name, "warp");
  validateYarn(weft, name, "weft");
  requireFabric(std::isfinite(warp_crimp) && warp_crimp >= 0.0 && warp_crimp <= 1.0, name,
                "warp_crimp must be in [0, 1]");
  requireFabric(std::isfinite(weft_crimp) && weft_crimp >= 0.0 && weft_crimp <= 1.0, name,
                "weft_crimp must be in [0, 1]");
  requireFabric(std::isfinite(shear_rigidity) && shear_rigidity >= 0.0, name,
                "shear_rigidity must be >= 0 [N/m]");
  for (const FabricVertexIndex& p : pinned) {
    requireFabric(p.row >= -picks && p.row < picks && p.column >= -ends && p.column < ends, name,
                  "pinned vertex (" + std::to_string(p.row) + ", " + std::to_string(p.column) +
                      ") out of range: row in " + range(picks) + ", column in " + range(ends));
  }
  for (const FabricSlit& slit : slits) {
    const int yarns = yarnCount(slit.family);
    const int segments = segmentsPerYarn(slit.family);
    requireFabric(
        slit.first_yarn >= 0 && slit.first_yarn <= slit.last_yarn && slit.last_yarn < yarns, name,
        std::string("slit across ") + familyName(slit.family) + " yarns " +
            std::to_string(slit.first_yarn) + ".." + std::to_string(slit.last_yarn) +
            ": need 0 <= first_yarn <= last_yarn < " + std::to_string(yarns));
    requireFabric(slit.segment >= 0 && slit.segment < segments, name,
                  "slit segment " + std::to_string(slit.segment) + " out of range [0, " +
                      std::to_string(segments - 1) + "]");
  }
}

}  // namespace yarn_tearing
