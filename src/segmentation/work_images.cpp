#include "segmentation/work_images.hpp"

#include <opencv2/imgproc.hpp>

namespace projtrack {

namespace {

cv::Mat wrap(const std::uint8_t* data, int w, int h, std::ptrdiff_t stride, int type) {
  return {h, w, type, const_cast<std::uint8_t*>(data), static_cast<std::size_t>(stride)};
}

// The frame's chroma as Cr, Cb planes at the work size, into the two last channels of `ycrcb`.
void resample_chroma(const ColorView& frame, cv::Size work, cv::Mat& ycrcb, cv::Mat& chroma) {
  const ChromaView& c = frame.chroma;
  const int cw = (frame.luma.width + (1 << c.shift_x) - 1) >> c.shift_x;
  const int ch = (frame.luma.height + (1 << c.shift_y) - 1) >> c.shift_y;
  cv::Mat planes[2];
  if (c.pixel_stride == 2 && c.v == c.u + 1) {  // interleaved, U first (NV12)
    cv::resize(wrap(c.u, cw, ch, c.stride, CV_8UC2), chroma, work, 0, 0, cv::INTER_AREA);
    cv::split(chroma, planes);
    std::swap(planes[0], planes[1]);
  } else if (c.pixel_stride == 2 && c.u == c.v + 1) {  // interleaved, V first (NV21)
    cv::resize(wrap(c.v, cw, ch, c.stride, CV_8UC2), chroma, work, 0, 0, cv::INTER_AREA);
    cv::split(chroma, planes);
  } else {
    cv::resize(wrap(c.v, cw, ch, c.stride, CV_8U), planes[0], work, 0, 0, cv::INTER_AREA);
    cv::resize(wrap(c.u, cw, ch, c.stride, CV_8U), planes[1], work, 0, 0, cv::INTER_AREA);
  }
  const int from_to[] = {0, 1, 1, 2};
  cv::mixChannels(planes, 2, &ycrcb, 1, from_to, 2);
}

}  // namespace

void build_work_images(const ColorView& frame, int scale, WorkImages& out) {
  const ImageView& l = frame.luma;
  out.scale = std::max(1, scale);
  out.frame_width = l.width;
  out.frame_height = l.height;
  const cv::Size work((l.width + out.scale - 1) / out.scale,
                      (l.height + out.scale - 1) / out.scale);
  cv::resize(wrap(l.data, l.width, l.height, l.stride, CV_8U), out.gray, work, 0, 0,
             cv::INTER_AREA);
  if (!frame.has_chroma()) {
    cv::cvtColor(out.gray, out.bgr, cv::COLOR_GRAY2BGR);
    return;
  }
  out.ycrcb.create(work, CV_8UC3);
  const int luma_to[] = {0, 0};
  cv::mixChannels(&out.gray, 1, &out.ycrcb, 1, luma_to, 1);
  resample_chroma(frame, work, out.ycrcb, out.chroma);
  cv::cvtColor(out.ycrcb, out.bgr, cv::COLOR_YCrCb2BGR);
}

}  // namespace projtrack
