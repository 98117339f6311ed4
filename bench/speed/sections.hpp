// The sections of projtrack-speed, one file each; each writes its rows to speed.csv (output.hpp).
// main.cpp runs them in order.
#pragma once

#include <memory>
#include <vector>

#include "clip.hpp"

namespace projtrack::bench {

// Sections 1–3 (per_frame.cpp): every method in the element against a frame copy and the peers
// (Canny + floodFill, cvtracker MOSSE when `have_cvtracker`), on one clip.
void compare_with_peers(Clip& clip, int rounds, int batch, bool have_cvtracker);

// Section 4 (object_size.cpp): the library's cost against the object's size, at two frame sizes.
void cost_by_object_size(const std::vector<double>& object_px, int rounds);

// Our box blur and Canny against OpenCV's on the regions the tracker asks for (edge_stages.cpp).
void edge_stages(const std::vector<double>& object_px, int rounds, int batch);

// Section 5 (allocations.cpp): heap allocations per frame in steady state, and memory over
// `frames` frames.
void allocations_and_memory(Clip& clip, int frames);

// Section 6 (streams.cpp): `streams` concurrent 30 fps streams of `frames_each` frames.
void streams_rows(const Clip& clip, int streams, int frames_each);

// Sections 7–8 (bounded.cpp): the worst frame on adversarial content with the defaults, and with
// settings at their extremes (more of them unless `quick`), against the ordinary clip.
void adversarial_defaults(const std::vector<std::unique_ptr<Clip>>& set, const Clip& ordinary,
                          int reps);
void extreme_settings(const std::vector<std::unique_ptr<Clip>>& set, const Clip& ordinary, int reps,
                      bool quick);

// Section 9 (interrupt.cpp): set_state(NULL) during a frame that would take minutes.
void interrupt_latency(int trials);

// Not times (outcomes.cpp): the work ordinary frames need and what the default budget changes;
// what each method makes of the real clip.
void ordinary_work(const Clip& clip);
void real_clip_statuses(const Clip& clip);

}  // namespace projtrack::bench
