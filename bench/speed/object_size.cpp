// Section 4 of projtrack-speed: the library's cost against the object's size.
#include <string>

#include "output.hpp"
#include "projtrack/method.hpp"
#include "projtrack/tracker.hpp"
#include "race.hpp"
#include "sections.hpp"

namespace projtrack::bench {

void cost_by_object_size(const std::vector<double>& object_px, int rounds) {
  for (auto [w, h] : {std::pair{640, 480}, std::pair{1920, 1080}}) {
    for (double px : object_px) {
      auto clip = generated_clip(w, h, px / (static_cast<double>(w) * h), 8, 0);  // in place
      std::vector<Contender> cs;
      std::vector<std::unique_ptr<Tracker>> trackers;
      for (Method method : kAllMethods) {
        trackers.push_back(std::make_unique<Tracker>());
        Tracker* t = trackers.back().get();
        TrackerParams tp;
        tp.acquisition = Acquisition::Manual;
        t->seed(clip->seeds[0]);
        cs.push_back({std::string(method_name(method)), [t, method, tp, c = clip.get()](int i) {
                        const ImageView g(c->gray[i].data, c->width, c->height,
                                          static_cast<std::ptrdiff_t>(c->gray[i].step));
                        t->track(g, EdgeParams{}, i / 30.0, method, Params{}, tp);
                      }});
      }
      race(cs, *clip, rounds, 8);
      for (Contender& c : cs) {
        row("size", clip.get(), c.name, "object_px_" + std::to_string(static_cast<int>(px)),
            median(c.per_frame_us));
      }
    }
  }
}

}  // namespace projtrack::bench
