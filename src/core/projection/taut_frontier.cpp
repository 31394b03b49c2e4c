#include "yarn_tearing/core/projection/taut_frontier.hpp"

#include <algorithm>

namespace yarn_tearing {

void TautFrontier::reset(std::size_t num_edges) {
  batch_.assign(num_edges, 0);
  seen_.assign(num_edges, 0);
  gone_.assign(num_edges, 0);
  joined_.clear();
  pass_ = 0;
  batches_ = 0;
  peel_batch_ = 0;
  budget_scale_ = 1.0;
}

void TautFrontier::beginPass(const std::vector<std::uint8_t>& candidate,
                             const std::vector<std::uint8_t>& active,
                             const std::vector<double>& multiplier) {
  ++pass_;
  joined_.clear();
  peel_batch_ = 0;
  for (std::size_t e = 0; e < batch_.size(); ++e) {
    if (candidate[e] && active[e] && multiplier[e] < 0.0) {
      peel_batch_ = std::max(peel_batch_, batch_[e]);
    }
  }
  if (peel_batch_ > 0) budget_scale_ *= 0.5;
}

void TautFrontier::left(std::size_t e) {
  gone_[e] = pass_;
  batch_[e] = 0;
}

void TautFrontier::joined(std::size_t e) {
  batch_[e] = 0;
  joined_.push_back(static_cast<std::uint32_t>(e));
}

void TautFrontier::grow(const EdgeSet& edges, const EdgeIncidence& incidence,
                        const std::vector<std::uint8_t>& candidate,
                        const std::vector<double>& stretch, std::vector<std::uint8_t>& active) {
  if (joined_.empty()) return;
  const int batch = ++batches_;
  for (const std::uint32_t start : joined_) {
    const double budget = budget_scale_ * stretch[start];
    seen_[start] = pass_;
    stack_.assign(1, WalkStep{start, kNoVertex, 0.0});
    while (!stack_.empty()) {
      const WalkStep step = stack_.back();
      stack_.pop_back();
      for (const std::uint32_t v : {edges.vertex_a[step.edge], edges.vertex_b[step.edge]}) {
        if (v == step.entry) continue;
        for (const std::uint32_t* it = incidence.begin(v); it != incidence.end(v); ++it) {
          const std::uint32_t f = *it;
          if (!candidate[f] || seen_[f] == pass_ || gone_[f] == pass_) continue;
          if (active[f]) {
            seen_[f] = pass_;
            stack_.push_back(WalkStep{f, v, step.slack_used});
            continue;
          }
          const double slack_used = step.slack_used + std::max(-stretch[f], 0.0);
          if (slack_used >= budget) continue;
          seen_[f] = pass_;
          active[f] = 1;
          batch_[f] = batch;
          stack_.push_back(WalkStep{f, v, slack_used});
        }
      }
    }
  }
}

}  // namespace yarn_tearing
