#include "segmentation/work_images.hpp"

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace projtrack {

namespace {

cv::Mat wrap(const std::uint8_t* data, int w, int h, std::ptrdiff_t stride, int type) {
  return {h, w, type, const_cast<std::uint8_t*>(data), static_cast<std::size_t>(stride)};
}

// One chroma component as a plane: in place when its samples are adjacent (planar formats),
// else gathered sample by sample (NV12's pairs, YUY2's and UYVY's macro-pixels): a view with a
// wider element would read past the last row's end.
cv::Mat plane_of(const std::uint8_t* c, int w, int h, const ChromaView& view, cv::Mat& gathered) {
  if (view.pixel_stride == 1) return wrap(c, w, h, view.stride, CV_8U);
  gathered.create(h, w, CV_8U);
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* in = c + static_cast<std::ptrdiff_t>(y) * view.stride;
    std::uint8_t* out = gathered.ptr<std::uint8_t>(y);
    for (int x = 0; x < w; ++x) out[x] = in[static_cast<std::ptrdiff_t>(x) * view.pixel_stride];
  }
  return gathered;
}

// The frame's chroma within `part` (frame px) as Cr, Cb planes of `work` size, mapped by `range`
// (a one-channel table: OpenCV's LUT of a three-channel table is not vectorised, 0.16 ms at
// 427×240), into the two last channels of `ycrcb`.
void resample_chroma(const ColorView& frame, const cv::Rect& part, const cv::Mat& range,
                     cv::Size work, WorkImages& out, cv::Mat ycrcb) {
  const ChromaView& c = frame.chroma;
  const int cw = (frame.luma.width + (1 << c.shift_x) - 1) >> c.shift_x;
  const int ch = (frame.luma.height + (1 << c.shift_y) - 1) >> c.shift_y;
  const cv::Rect in = cv::Rect(cv::Point(part.x >> c.shift_x, part.y >> c.shift_y),
                               cv::Point((part.br().x + (1 << c.shift_x) - 1) >> c.shift_x,
                                         (part.br().y + (1 << c.shift_y) - 1) >> c.shift_y)) &
                      cv::Rect(0, 0, cw, ch);
  cv::resize(plane_of(c.v, cw, ch, c, out.chroma)(in), out.cr, work, 0, 0, cv::INTER_AREA);
  cv::resize(plane_of(c.u, cw, ch, c, out.chroma)(in), out.cb, work, 0, 0, cv::INTER_AREA);
  cv::LUT(out.cr, range, out.cr);
  cv::LUT(out.cb, range, out.cb);
  const cv::Mat planes[] = {out.cr, out.cb};
  const int from_to[] = {0, 1, 1, 2};
  cv::mixChannels(planes, 2, &ycrcb, 1, from_to, 2);
}

}  // namespace

FullRangeTables::FullRangeTables() : luma(1, 256, CV_8U), chroma(1, 256, CV_8U) {
  for (int v = 0; v < 256; ++v) {
    luma.at<std::uint8_t>(v) =
        cv::saturate_cast<std::uint8_t>(std::lround((v - 16) * 255.0 / 219.0));
    chroma.at<std::uint8_t>(v) =
        cv::saturate_cast<std::uint8_t>(std::lround(128 + (v - 128) * 255.0 / 224.0));
  }
}

const FullRangeTables& full_range_tables() {
  static const FullRangeTables tables;
  return tables;
}

cv::Size work_size(int width, int height, int scale) {
  const int s = std::max(1, scale);
  return {(width + s - 1) / s, (height + s - 1) / s};
}

cv::Rect frame_part(const cv::Rect& region, int scale, int width, int height) {
  const int s = std::max(1, scale);
  return cv::Rect(
             cv::Point(region.x * s, region.y * s),
             cv::Point(std::min(region.br().x * s, width), std::min(region.br().y * s, height))) &
         cv::Rect(0, 0, width, height);
}

void build_work_images(const ColorView& frame, int scale, WorkImages& out) {
  const cv::Size work = work_size(frame.luma.width, frame.luma.height, scale);
  build_work_images(frame, scale, cv::Rect({0, 0}, work), out);
}

void build_work_images(const ColorView& frame, int scale, const cv::Rect& region_in,
                       WorkImages& out) {
  const ImageView& l = frame.luma;
  const cv::Size work = work_size(l.width, l.height, scale);
  if (out.scale != std::max(1, scale) || out.frame_width != l.width ||
      out.frame_height != l.height || out.gray.size() != work) {
    out.gray.create(work, CV_8U);
    out.bgr.create(work, CV_8UC3);
  }
  out.scale = std::max(1, scale);
  out.frame_width = l.width;
  out.frame_height = l.height;
  const cv::Rect region = region_in & cv::Rect({0, 0}, work);
  out.filled = region;
  if (region.empty()) return;
  const cv::Rect part = frame_part(region, out.scale, l.width, l.height);
  cv::Mat gray = out.gray(region);
  cv::resize(wrap(l.data, l.width, l.height, l.stride, CV_8U)(part), gray, region.size(), 0, 0,
             cv::INTER_AREA);
  cv::LUT(gray, full_range_tables().luma, gray);
  cv::Mat bgr = out.bgr(region);
  if (!frame.has_chroma()) {
    cv::cvtColor(gray, bgr, cv::COLOR_GRAY2BGR);
    return;
  }
  out.ycrcb.create(region.size(), CV_8UC3);
  const int luma_to[] = {0, 0};
  cv::mixChannels(&gray, 1, &out.ycrcb, 1, luma_to, 1);
  resample_chroma(frame, part, full_range_tables().chroma, region.size(), out, out.ycrcb);
  cv::cvtColor(out.ycrcb, bgr, cv::COLOR_YCrCb2BGR);
}

}  // namespace projtrack
