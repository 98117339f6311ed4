// The colour model against OpenCV's histograms, on the object model's work region of a real
// frame with the hand's mask as the object and a ring around it: see cases.hpp.
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

#include "appearance/appearance_model.hpp"
#include "cases.hpp"
#include "core/work_frame.hpp"
#include "projtrack/object_model_params.hpp"
#include "scene.hpp"

namespace projtrack::handwritten {
namespace {

// The object and the ring around it in the work region `wr` (work coordinates).
void object_and_ring(const Rect& wr, cv::Mat& object, cv::Mat& ring) {
  const cv::Mat hand =
      synthetic::make_scene(synthetic::SceneSpec(640, 480, synthetic::Object::Hand), {}).mask;
  const cv::Rect box = cv::boundingRect(hand);
  cv::resize(hand(box), object, cv::Size(wr.width / 2, wr.height / 2), 0, 0, cv::INTER_NEAREST);
  cv::copyMakeBorder(object, object, wr.height / 4, wr.height - wr.height / 2 - wr.height / 4,
                     wr.width / 4, wr.width - wr.width / 2 - wr.width / 4, cv::BORDER_CONSTANT,
                     cv::Scalar(0));
  object &= 1;
  cv::Mat grown;
  cv::dilate(object, grown, cv::getStructuringElement(cv::MORPH_RECT, {9, 9}));
  ring = grown - object;
}

void histograms(const Frame& f, const Effort& e, std::FILE* out) {
  const Rect fr{f.width / 4, f.height / 4, f.width / 2, f.height / 2};
  const int s =
      work_scale(static_cast<double>(fr.width) * fr.height, ObjectModelParams{}.work_pixels);
  const Rect wr = to_work(fr, s);
  WorkFrame wf;
  wf.build(f.color(), s, wr);
  const ColorView& view = wf.view();
  cv::Mat object, ring;
  object_and_ring(wr, object, ring);
  Mask m_object, m_ring;
  to_mask(object, m_object);
  to_mask(ring, m_ring);
  m_object.translate(wr.x, wr.y);
  m_ring.translate(wr.x, wr.y);
  AppearanceModel model;
  std::vector<std::uint8_t> likelihood;
  const auto plane = [&](const std::uint8_t* p) {
    return cv::Mat(wr.height, wr.width, CV_8U, const_cast<std::uint8_t*>(p));
  };
  const cv::Mat planes[] = {plane(view.luma.data), plane(view.chroma.v), plane(view.chroma.u)};
  cv::Mat yvu(wr.height, wr.width, CV_8UC3), h_object, h_ring, ratio, back(yvu.size(), CV_8U);
  const int channels[] = {0, 1, 2}, sizes[] = {16, 32, 32};
  const float range[] = {0, 256};
  const float* ranges[] = {range, range, range};
  Row r{"colour histograms, learned and back-projected (16x32x32 bins)",
        "src/appearance/appearance_model.cpp AppearanceModel::learn + likelihood",
        "cv::merge + cv::calcHist x2 + ratio + cv::calcBackProject",
        f.name + " object model's work region (scale " + std::to_string(s) + ": " +
            std::to_string(wr.width) + "x" + std::to_string(wr.height) + ")",
        "not compared (ours smooths along luma and weighs by a prior)"};
  const Duel d = duel(
      [&] {
        model.learn(view, {wr.x, wr.y}, m_object, m_ring, 0.1);
        model.likelihood(view, {wr.x, wr.y}, wr, likelihood);
      },
      [&] {
        cv::merge(planes, 3, yvu);
        cv::calcHist(&yvu, 1, channels, object, h_object, 3, sizes, ranges);
        cv::calcHist(&yvu, 1, channels, ring, h_ring, 3, sizes, ranges);
        cv::add(h_object, h_ring, ratio);
        cv::divide(h_object, ratio, ratio, 255.0);
        cv::calcBackProject(&yvu, 1, channels, ratio, back, ranges);
      },
      e.rounds, e.calls);
  write_row(out, r, d);

  // Mean shift: ours is three steps inside SilhouetteModel::recentre (private, on the model's own
  // likelihood): the library's alone, on the likelihood just made.
  const cv::Mat l(wr.height, wr.width, CV_8U, likelihood.data());
  cv::Mat object_like;
  cv::threshold(l, object_like, 127, 255, cv::THRESH_TOZERO);
  const cv::Rect start = cv::boundingRect(object) + cv::Point(3, 2);
  Row ms{"mean shift of a window on the likelihood (3 steps)",
         "src/appearance/silhouette_model.cpp SilhouetteModel::recentre",
         "cv::meanShift 3 iterations", r.input, ""};
  const Duel lib = duel([] {},
                        [&] {
                          cv::Rect w = start;
                          cv::meanShift(object_like, w, {cv::TermCriteria::COUNT, 3, 0});
                        },
                        e.rounds, e.calls);
  write_library_only(out, ms, lib.library,
                     "ours is a private step of SilhouetteModel, not callable alone");
}

}  // namespace

void colour_duels(const std::vector<Frame>& frames, const Effort& e, std::FILE* out) {
  for (const Frame& f : frames) histograms(f, e, out);
}

}  // namespace projtrack::handwritten
