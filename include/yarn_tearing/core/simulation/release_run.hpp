#pragma once

#include <cstdint>
#include <vector>

#include "yarn_tearing/core/model/edge_incidence.hpp"
#include "yarn_tearing/core/model/scene.hpp"

namespace yarn_tearing {

/// How long the elastic wave a tear releases takes to unload its yarn's loaded run [s]: from
/// each edge of `torn` (global ids, torn already) along its yarn on either side, over the intact
/// edges that carry at least half the tension of the more loaded of the torn edge's two
/// neighbours, the longer side's rest length (L0) over c = sqrt(E / rho) of the torn edge's
/// material; the longest over `torn`, 0 for none. The run goes on through a vertex where exactly
/// one other intact edge of the same yarn (a fabric's family) meets it, and stops at branches
/// and ends. A taut yarn's run is the whole yarn; the yarn torn at a fabric's tear tip, which the
/// crossing yarns unload within a few cells, runs a few cells.
double releaseCrossingTime(const Scene& scene, const EdgeIncidence& incidence,
                           const std::vector<std::uint32_t>& torn);

}  // namespace yarn_tearing
