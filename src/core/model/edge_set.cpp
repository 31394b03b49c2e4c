#include "yarn_tearing/core/model/edge_set.hpp"

namespace yarn_tearing {

void EdgeSet::add(std::uint32_t a, std::uint32_t b, std::uint32_t yarn_index, double rest,
                  double cross_section, double strength) {
  vertex_a.push_back(a);
  vertex_b.push_back(b);
  yarn.push_back(yarn_index);
  original_rest_length.push_back(rest);
  rest_length.push_back(rest);
  area.push_back(cross_section);
  strength_factor.push_back(strength);
  breaking_strain.push_back(0.0);  // from the curve: assignBreakingStrains
  strain_limit.push_back(0.0);
  plastic_strain.push_back(0.0);
  tension.push_back(0.0);
  spring_tension.push_back(0.0);
  stress.push_back(0.0);
  strain.push_back(0.0);
  strain_rate.push_back(0.0);
  loading_time.push_back(0.0);
  loading_start_strain.push_back(0.0);
  rate_factor.push_back(1.0);
  broken.push_back(0);
}

}  // namespace yarn_tearing
