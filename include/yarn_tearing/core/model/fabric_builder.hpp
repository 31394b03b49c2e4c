#pragma once

#include "yarn_tearing/core/model/fabric_spec.hpp"
#include "yarn_tearing/core/model/scene.hpp"

namespace yarn_tearing {

/// Appends a flat fabric at rest to `scene` (the spec validated beforehand): its picks x ends
/// vertices, its warp segments (group "<name>/warp"), then its weft segments (group
/// "<name>/weft"), its shear cells, pins and slits. A vertex's mass [kg] is half of each segment
/// meeting it, m = rho A L0 with L0 = spacing (1 + crimp).
void addFabric(Scene& scene, const FabricSpec& spec);

}  // namespace yarn_tearing
