// The frames the report's contact sheets show: for each request (a clip, a run and its frames),
// the element's own overlay (draw=true) re-run with the run's properties, or, for a box tracker,
// the decoded frame (the report draws its box).
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include "clip.hpp"

namespace projtrack::bench {

struct RenderRequest {
  std::string entry, slug, props;  // props empty: the decoded frame
  std::set<int> frames;
};

// FILE's rows: entry,slug,props,frames (frames separated by spaces; props quoted when needed).
std::vector<RenderRequest> read_render_requests(const std::string& path);

// Writes DIR/<entry>/<slug>/NNN.jpg for each requested frame of the clip.
void render(const Clip& c, const RenderRequest& r, const std::string& dir);

}  // namespace projtrack::bench
