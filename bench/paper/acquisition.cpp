// Auto acquisition's strategies on moving objects: see acquisition.hpp.
#include "acquisition.hpp"

#include <functional>
#include <string>
#include <vector>

#include "scene.hpp"
#include "sequence.hpp"

namespace projtrack::bench {

using synthetic::frame_at;
using synthetic::Object;
using synthetic::run_sequence;
using synthetic::SceneSpec;

void acquisition(const Options& opt, std::ostream& csv, Progress& progress) {
  csv << "sequence,instance,strategy,acquired_frame,correct,sane_after,frames\n";
  struct Sequence {
    std::string name;
    std::function<SceneSpec(int frame, int instance)> spec;
  };
  const std::vector<Sequence> sequences = {
      {"hand-moving",
       [](int i, int k) { return frame_at(Object::Hand, 180 + 30 * k + 4.0 * i, 250, i); }},
      {"sphere-moving",
       [](int i, int k) {
         return frame_at(Object::Sphere, 200 + 3.0 * i, 180 + 20 * k + 2.0 * i, i);
       }},
      {"hand-slow",
       [](int i, int k) { return frame_at(Object::Hand, 260 + 25 * k + 1.5 * i, 250, i); }},
      {"small-sphere",
       [](int i, int k) { return frame_at(Object::Sphere, 200 + 40 * k + 3.0 * i, 240, i, 0.5); }},
      {"hand-with-distractor",
       [](int i, int k) {
         SceneSpec s = frame_at(Object::Hand, 200 + 20 * k + 4.0 * i, 280, i);
         s.distractor = Point2d{560 - 5.0 * i, 80 + 10.0 * k};
         return s;
       }},
      {"hand-with-specks-and-gaps",
       [](int i, int k) {
         SceneSpec s = frame_at(Object::Hand, 200 + 30 * k + 4.0 * i, 250, i);
         s.spurious = true;
         s.gap_rate = 0.01;
         return s;
       }},
  };
  const int instances = opt.quick ? 1 : 4, frames = kAcquisitionFrames;
  for (const Sequence& seq : sequences) {
    for (int k = 0; k < instances; ++k) {
      for (auto [name, strategy] : kStrategies) {
        TrackerParams tp;
        tp.model = ObjectModelKind::Edges;  // the strategies are the edges model's
        tp.strategy = strategy;
        const auto steps = run_sequence(
            frames, [&](int i) { return seq.spec(i, k); }, tp);
        int acquired = -1, sane = 0;
        for (int i = 0; i < frames; ++i) {
          if (acquired < 0 && steps[i].result.acquired) acquired = i;
          if (acquired >= 0) sane += steps[i].sane;
        }
        csv << seq.name << ',' << k << ',' << name << ',' << acquired << ','
            << (acquired >= 0 && steps[acquired].sane) << ','
            << (acquired >= 0 ? static_cast<double>(sane) / (frames - acquired) : 0.0) << ','
            << frames << '\n';
      }
    }
    progress.advance("acquisition " + seq.name);
  }
}

}  // namespace projtrack::bench
