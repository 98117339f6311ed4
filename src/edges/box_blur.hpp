// A 3×3 box blur of 8-bit images into a reusable buffer: the same result as
// cv::blur(src, dst, {3, 3}) with BORDER_REPLICATE, with no per-call allocation.
#pragma once

#include <cstdint>

#include "projtrack/geometry.hpp"
#include "projtrack/image_view.hpp"

namespace projtrack {

// Blurs `region` of `src` into `dst` (region.width × region.height, rows `dst_stride` apart).
// Pixels around the region are read where `src` has them and replicated at `src`'s own border,
// so the region's blur equals the whole image's blur cropped. `region` must lie inside `src`.
void box_blur3(const ImageView& src, const Rect& region, std::uint8_t* dst,
               std::ptrdiff_t dst_stride);

}  // namespace projtrack
