#include "frame_color.hpp"

#include <cstring>

#include "projtrack/color_conversion.hpp"

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
    case GST_VIDEO_FORMAT_A420:  // I420 and an alpha plane
      return true;
    default:
      return false;
  }
}

bool is_packed_yuv(GstVideoFormat format) {
  return format == GST_VIDEO_FORMAT_YUY2 || format == GST_VIDEO_FORMAT_UYVY ||
         format == GST_VIDEO_FORMAT_AYUV;
}

namespace {

// Components 1 and 2 are U and V whatever their planes (YV12 swaps them, NV12 interleaves them,
// YUY2 and UYVY pack them between the luma samples).
ChromaView chroma_in_place(const GstVideoFrame* frame) {
  ChromaView c;
  c.u = static_cast<const std::uint8_t*>(GST_VIDEO_FRAME_COMP_DATA(frame, 1));
  c.v = static_cast<const std::uint8_t*>(GST_VIDEO_FRAME_COMP_DATA(frame, 2));
  c.stride = GST_VIDEO_FRAME_COMP_STRIDE(frame, 1);
  c.pixel_stride = GST_VIDEO_FRAME_COMP_PSTRIDE(frame, 1);
  c.shift_x = GST_VIDEO_FORMAT_INFO_W_SUB(frame->info.finfo, 1);
  c.shift_y = GST_VIDEO_FORMAT_INFO_H_SUB(frame->info.finfo, 1);
  return c;
}

// The frame's luma and chroma as its buffer stores them (in place where the library can read
// them), RGB converted.
ColorView as_stored(const GstVideoFrame* frame, std::vector<std::uint8_t>& buffer) {
  const int width = GST_VIDEO_FRAME_WIDTH(frame), height = GST_VIDEO_FRAME_HEIGHT(frame);
  if (has_luma_plane(GST_VIDEO_FRAME_FORMAT(frame))) {
    const auto* luma = static_cast<const std::uint8_t*>(GST_VIDEO_FRAME_PLANE_DATA(frame, 0));
    // One row has no stride to speak of (a meta may say 0).
    const std::ptrdiff_t stride = height == 1 ? width : GST_VIDEO_FRAME_PLANE_STRIDE(frame, 0);
    const bool chroma = GST_VIDEO_FRAME_N_COMPONENTS(frame) >= 3;
    // The library reads U and V with one stride; a meta may give their planes two.
    const bool gather_chroma =
        chroma && GST_VIDEO_FRAME_COMP_STRIDE(frame, 1) != GST_VIDEO_FRAME_COMP_STRIDE(frame, 2);
    const int cw = GST_VIDEO_FRAME_COMP_WIDTH(frame, 1), ch = GST_VIDEO_FRAME_COMP_HEIGHT(frame, 1);
    const std::size_t luma_copy = stride < 0 ? static_cast<std::size_t>(width) * height : 0;
    const std::size_t chroma_copy = gather_chroma ? static_cast<std::size_t>(cw) * ch : 0;
    buffer.resize(luma_copy + 2 * chroma_copy);
    ColorView c;
    if (stride >= 0) {
      c.luma = ImageView(luma, width, height, stride);
    } else {
      // Bottom-up rows: the library reads rows at rising addresses, so they are copied in order
      // (the chroma, read through signed offsets, stays in place).
      for (int y = 0; y < height; ++y)
        std::memcpy(buffer.data() + static_cast<std::size_t>(y) * width, luma + y * stride, width);
      c.luma = ImageView(buffer.data(), width, height, width);
    }
    if (gather_chroma) {
      std::uint8_t* u = buffer.data() + luma_copy;
      std::uint8_t* v = u + chroma_copy;
      for (int k : {1, 2}) {
        gather_component(static_cast<const std::uint8_t*>(GST_VIDEO_FRAME_COMP_DATA(frame, k)),
                         GST_VIDEO_FRAME_COMP_PSTRIDE(frame, k),
                         GST_VIDEO_FRAME_COMP_STRIDE(frame, k), cw, ch, k == 1 ? u : v, cw);
      }
      const ChromaView in_place = chroma_in_place(frame);
      c.chroma = {u, v, cw, 1, in_place.shift_x, in_place.shift_y};
    } else if (chroma) {
      c.chroma = chroma_in_place(frame);
    }
    return c;
  }
  if (is_packed_yuv(GST_VIDEO_FRAME_FORMAT(frame))) {
    // The library reads luma rows of adjacent bytes: YUY2's and UYVY's every second byte (AYUV's
    // every fourth) is gathered once (a row copy's cost); their chroma is read in place.
    buffer.resize(static_cast<std::size_t>(width) * height);
    gather_component(static_cast<const std::uint8_t*>(GST_VIDEO_FRAME_COMP_DATA(frame, 0)),
                     GST_VIDEO_FRAME_COMP_PSTRIDE(frame, 0), GST_VIDEO_FRAME_COMP_STRIDE(frame, 0),
                     width, height, buffer.data(), width);
    return {ImageView(buffer.data(), width, height, width), chroma_in_place(frame), {}};
  }
  // Packed RGB: components 0, 1, 2 are R, G, B whatever their order in memory.
  const auto comp = [&](int i) {
    return static_cast<const std::uint8_t*>(GST_VIDEO_FRAME_COMP_DATA(frame, i));
  };
  const int pstride = GST_VIDEO_FRAME_COMP_PSTRIDE(frame, 0);
  const std::ptrdiff_t stride = GST_VIDEO_FRAME_COMP_STRIDE(frame, 0);
  return packed_rgb_to_color(comp(0), comp(1), comp(2), pstride, stride, width, height, buffer);
}

// Whether the frame stores full-range values: its caps' colorimetry says so, or says nothing for
// gray (GStreamer's default: GRAY8 full range, YUV limited; videoconvert maps I420's 16-235 luma
// to GRAY8's 0-255). RGB is converted to video range by the library itself.
bool full_range(const GstVideoFrame* frame) {
  const GstVideoInfo* info = &frame->info;
  if (GST_VIDEO_INFO_IS_RGB(info)) return false;
  const GstVideoColorRange range = info->colorimetry.range;
  return range == GST_VIDEO_COLOR_RANGE_0_255 ||
         (range == GST_VIDEO_COLOR_RANGE_UNKNOWN && GST_VIDEO_INFO_IS_GRAY(info));
}

}  // namespace

ColorView frame_color(const GstVideoFrame* frame, FrameBuffers& buffers) {
  const ColorView stored = as_stored(frame, buffers.read);
  return full_range(frame) ? full_to_video_range(stored, buffers.video_range) : stored;
}

}  // namespace projtrack::gst
