#include "frame_gray.hpp"

#include "gray_conversion.hpp"

namespace projtrack::gst {

bool has_luma_plane(GstVideoFormat format) {
  switch (format) {
    case GST_VIDEO_FORMAT_GRAY8:
    case GST_VIDEO_FORMAT_I420:
    case GST_VIDEO_FORMAT_YV12:
    case GST_VIDEO_FORMAT_NV12:
    case GST_VIDEO_FORMAT_NV21:
    case GST_VIDEO_FORMAT_Y42B:
    case GST_VIDEO_FORMAT_Y444:
      return true;
    default:
      return false;
  }
}

ImageView frame_gray(const GstVideoFrame* frame, std::vector<std::uint8_t>& buffer) {
  const int width = GST_VIDEO_FRAME_WIDTH(frame), height = GST_VIDEO_FRAME_HEIGHT(frame);
  if (has_luma_plane(GST_VIDEO_FRAME_FORMAT(frame))) {
    return ImageView(static_cast<const std::uint8_t*>(GST_VIDEO_FRAME_PLANE_DATA(frame, 0)), width,
                     height, GST_VIDEO_FRAME_PLANE_STRIDE(frame, 0));
  }
  // Packed RGB: components 0, 1, 2 are R, G, B whatever their order in memory.
  buffer.resize(static_cast<std::size_t>(width) * height);
  const auto comp = [&](int c) {
    return static_cast<const std::uint8_t*>(GST_VIDEO_FRAME_COMP_DATA(frame, c));
  };
  packed_rgb_to_gray(comp(0), comp(1), comp(2), GST_VIDEO_FRAME_COMP_PSTRIDE(frame, 0),
                     GST_VIDEO_FRAME_COMP_STRIDE(frame, 0), width, height, buffer.data(), width);
  return ImageView(buffer.data(), width, height, width);
}

}  // namespace projtrack::gst
