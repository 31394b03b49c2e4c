#include "yarn_tearing/core/model/fabric_segment.hpp"

namespace yarn_tearing {

const char* familyName(FabricFamily family) {
  return family == FabricFamily::kWarp ? "warp" : "weft";
}

}  // namespace yarn_tearing
