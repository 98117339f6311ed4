// Our box blur and Canny against cv::blur and cv::Canny (projtrack-speed).
#include <opencv2/imgproc.hpp>

#include "edges/box_blur.hpp"
#include "edges/canny.hpp"
#include "output.hpp"
#include "projtrack/method.hpp"
#include "projtrack/tracker.hpp"
#include "race.hpp"
#include "sections.hpp"
#include "models/edges/edge_region.hpp"

namespace projtrack::bench {

// Our box blur and Canny against cv::blur and cv::Canny, side by side on the same crops of the
// same frames: the regions the tracker asks for around objects of each size (and whole frames,
// what searching costs). Canny runs on the blurred crop, with the element's thresholds.
void edge_stages(const std::vector<double>& object_px, int rounds, int batch) {
  const EdgeParams ep;
  const Method method = method_from_name(kDefaultMethod).value_or(Method::GridFilling);
  struct Case {
    std::unique_ptr<Clip> clip;
    Rect region;
    double object_px;  // 0: the whole frame
  };
  std::vector<Case> cases;
  for (double px : object_px) {
    auto clip = generated_clip(640, 480, px / (640.0 * 480), 8, 0);
    // The region the edges model computes edges in around the object at rest.
    const Rect region = edge_region(clip->first_box, {0, 0}, method, Params{}, TrackerParams{},
                                    clip->width, clip->height);
    cases.push_back({std::move(clip), region, px});
  }
  for (auto [w, h] : {std::pair{640, 480}, std::pair{1920, 1080}})
    cases.push_back({generated_clip(w, h, 0.10, 4, 0), Rect{0, 0, w, h}, 0});
  for (const Case& k : cases) {
    const Clip& clip = *k.clip;
    const Rect region = k.region;
    const cv::Rect roi(region.x, region.y, region.width, region.height);
    std::vector<cv::Mat> crops, blurred;  // contiguous, as a region's buffers are
    for (const cv::Mat& g : clip.gray) {
      crops.push_back(g(roi).clone());
      cv::Mat b;
      cv::blur(crops.back(), b, {3, 3}, {-1, -1}, cv::BORDER_REPLICATE);
      blurred.push_back(b);
    }
    cv::Mat out(region.height, region.width, CV_8U), edges;
    CannyDetector canny;
    const auto view = [](const cv::Mat& m) {
      return ImageView(m.data, m.cols, m.rows, static_cast<std::ptrdiff_t>(m.step));
    };
    std::vector<Contender> cs;
    cs.push_back({"projtrack box blur", [&](int i) {
                    box_blur3(view(crops[i]), {0, 0, region.width, region.height}, out.data,
                              static_cast<std::ptrdiff_t>(out.step));
                  }});
    cs.push_back({"cv::blur", [&](int i) {
                    cv::blur(crops[i], out, {3, 3}, {-1, -1}, cv::BORDER_REPLICATE);
                  }});
    cs.push_back(
        {"projtrack Canny", [&](int i) { canny.detect(view(blurred[i]), ep.low, ep.high); }});
    cs.push_back(
        {"cv::Canny", [&](int i) { cv::Canny(blurred[i], edges, ep.low, ep.high, 3, false); }});
    race(cs, clip, rounds, batch);
    const std::string key =
        "region_" + std::to_string(region.width) + "x" + std::to_string(region.height);
    row("edge_region", &clip, key, "object_px", k.object_px);
    for (const Contender& c : cs) row("edge_stages", &clip, c.name, key, median(c.per_frame_us));
    row("edge_ratio", &clip, "cv::blur / projtrack box blur", key, median_ratio(cs[1], cs[0]));
    row("edge_ratio", &clip, "cv::Canny / projtrack Canny", key, median_ratio(cs[3], cs[2]));
  }
}

}  // namespace projtrack::bench
