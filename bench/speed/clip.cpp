// The clips of projtrack-speed: see clip.hpp.
#include "clip.hpp"

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "scene.hpp"
#include "sequence.hpp"

namespace projtrack::bench {
namespace {

using synthetic::frame_at;
using synthetic::make_scene;
using synthetic::Object;
using synthetic::Scene;
using synthetic::SceneSpec;

GstBuffer* buffer_of(const cv::Mat& packed) {
  const gsize n = packed.total() * packed.elemSize();
  GstBuffer* b = gst_buffer_new_allocate(nullptr, n, nullptr);
  gst_buffer_fill(b, 0, packed.data, n);
  return b;
}

}  // namespace

void add_frame(Clip& c, const cv::Mat& bgr_or_gray) {
  cv::Mat gray, bgr, rgb, i420;
  if (bgr_or_gray.channels() == 1) {
    gray = bgr_or_gray;
    cv::cvtColor(gray, bgr, cv::COLOR_GRAY2BGR);
  } else {
    bgr = bgr_or_gray;
    cv::cvtColor(bgr, gray, cv::COLOR_BGR2GRAY);
  }
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  if (bgr_or_gray.channels() == 1) {  // a grey scene: luma as rendered, neutral chroma
    i420.create(c.height * 3 / 2, c.width, CV_8UC1);
    gray.copyTo(i420.rowRange(0, c.height));
    i420.rowRange(c.height, i420.rows).setTo(128);
  } else {
    cv::cvtColor(bgr, i420, cv::COLOR_BGR2YUV_I420);
    gray = i420.rowRange(0, c.height).clone();  // the luma projtrack will read
  }
  c.gray.push_back(gray.clone());
  c.i420.push_back(buffer_of(i420));
  c.rgb.push_back(buffer_of(rgb));
}

std::unique_ptr<Clip> generated_clip(int w, int h, double share, int n, double swing) {
  auto c = std::make_unique<Clip>();
  c->name = "generated";
  c->width = w;
  c->height = h;
  const Scene probe = make_scene(SceneSpec(w, h), {});
  const double scale = std::sqrt(share * w * h / probe.true_area);
  for (int i = 0; i < n; ++i) {
    SceneSpec s = frame_at(Object::Sphere, w / 2 + swing * w * std::sin(2 * M_PI * i / n),
                           h / 2 + swing / 3 * h * std::cos(2 * M_PI * i / n), i, scale);
    s.width = w;
    s.height = h;
    const Scene scene = make_scene(s, {});
    add_frame(*c, scene.image);
    c->seeds.push_back(round_to_pixel(scene.true_centroid));
    if (i == 0) {
      cv::Rect b = cv::boundingRect(scene.mask);
      c->first_box = {b.x, b.y, b.width, b.height};
      c->object_share = scene.true_area / (static_cast<double>(w) * h);
    }
  }
  return c;
}

std::unique_ptr<Clip> real_clip(const std::string& path, int w, int h, int max_frames) {
  cv::VideoCapture cap(path);
  if (!cap.isOpened()) return nullptr;
  auto c = std::make_unique<Clip>();
  c->name = "real";
  c->width = w;
  c->height = h;
  cv::Mat frame, sized;
  while (static_cast<int>(c->gray.size()) < max_frames && cap.read(frame)) {
    cv::resize(frame, sized, cv::Size(w, h), 0, 0, cv::INTER_LINEAR);
    add_frame(*c, sized);
    c->seeds.push_back({w / 2, h / 2});
  }
  const int bw = static_cast<int>(w * std::sqrt(0.1)), bh = static_cast<int>(h * std::sqrt(0.1));
  c->first_box = {(w - bw) / 2, (h - bh) / 2, bw, bh};
  return c->gray.empty() ? nullptr : std::move(c);
}

std::unique_ptr<Clip> adversarial_clip(const synthetic::AdversaryInfo& a, int w, int h, int n) {
  auto c = std::make_unique<Clip>();
  c->name = a.name;
  c->width = w;
  c->height = h;
  for (int i = 0; i < n; ++i) {
    add_frame(*c, synthetic::adversarial_frame(a.kind, w, h, i));
    c->seeds.push_back({w / 2, h / 2});
  }
  return c;
}

}  // namespace projtrack::bench
