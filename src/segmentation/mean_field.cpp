#include "segmentation/mean_field.hpp"

#include <cmath>

namespace projtrack {

void mean_field(const CutProblem& pr, const ContrastField& f, const std::vector<float>& log_odds,
                int sweeps, std::vector<float>& q) {
  const int n = pr.cells();
  for (int s = 0; s < sweeps; ++s)
    for (int k = 0; k < n; ++k) {
      const int i = s % 2 ? n - 1 - k : k;
      if (pr.fixed[i] != CutProblem::kFree) continue;
      float field = log_odds[i];
      for (int d = 0; d < 8; ++d) {
        const float w = f.weight[8 * i + d];
        if (w > 0)
          field += kSmoothness * w * (2 * q[i + kNeighbourDy[d] * pr.w + kNeighbourDx[d]] - 1);
      }
      q[i] = 1.f / (1.f + std::exp(-field));
    }
}

}  // namespace projtrack
