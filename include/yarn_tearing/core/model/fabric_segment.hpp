#pragma once

#include <cstdint>

namespace yarn_tearing {

/// The two yarn families of a woven fabric.
enum class FabricFamily : std::uint8_t {
  kWarp = 0,  ///< the lengthwise yarns (ends): columns of the fabric's vertex grid
  kWeft = 1,  ///< the crosswise yarns (picks): rows of the fabric's vertex grid
};

/// Names one segment of one yarn of a fabric: the warp yarn (end) `yarn` runs down column `yarn`
/// and its segment `segment` joins rows `segment` and `segment + 1`; the weft yarn (pick) `yarn`
/// runs along row `yarn` and its segment `segment` joins columns `segment` and `segment + 1`.
struct FabricSegment {
  FabricFamily family = FabricFamily::kWarp;
  std::uint32_t yarn = 0;     ///< index of the yarn within its family [-]
  std::uint32_t segment = 0;  ///< index of the segment along that yarn [-]
};

/// "warp" or "weft".
const char* familyName(FabricFamily family);

}  // namespace yarn_tearing
