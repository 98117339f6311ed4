// Racing contenders: see race.hpp.
#include "race.hpp"

#include <algorithm>

namespace projtrack::bench {

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double median_ratio(const Contender& a, const Contender& b) {
  std::vector<double> r;
  for (std::size_t k = 0; k < a.per_frame_us.size() && k < b.per_frame_us.size(); ++k)
    r.push_back(a.per_frame_us[k] / b.per_frame_us[k]);
  return median(r);
}

void race(std::vector<Contender>& cs, const Clip& clip, int rounds, int batch) {
  const std::size_t n = clip.gray.size();
  for (Contender& c : cs)  // warm up: first acquisition, buffers sized
    for (int i = 0; i < batch; ++i) c.process(static_cast<int>(c.next++ % n));
  for (int r = 0; r < rounds; ++r) {
    for (std::size_t k = 0; k < cs.size(); ++k) {
      Contender& c = cs[(k + r) % cs.size()];
      const auto t0 = Clock::now();
      for (int i = 0; i < batch; ++i) c.process(static_cast<int>(c.next++ % n));
      c.per_frame_us.push_back(1e6 * seconds_since(t0) / batch);
    }
  }
}

}  // namespace projtrack::bench
