#include "segmentation/start_patch.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "segmentation/work_images.hpp"

namespace projtrack {

namespace {

// The 2 frame columns (or rows) each of `n` patch pixels over `length` frame px from `start`
// samples: at a quarter and three quarters of what it covers.
void sample_positions(int start, int length, int n, std::vector<int>& at) {
  at.resize(2 * static_cast<std::size_t>(n));
  for (int i = 0; i < 2 * n; ++i)
    at[i] = start + std::min(length - 1, static_cast<int>((i + 0.5) * length / (2.0 * n)));
}

}  // namespace

cv::Size patch_size(const cv::Rect& rect, double pixels) {
  const double k = std::min(1.0, std::sqrt(pixels / std::max(1, rect.area())));
  return {std::max(1, static_cast<int>(std::lround(rect.width * k))),
          std::max(1, static_cast<int>(std::lround(rect.height * k)))};
}

void read_patch(const ColorView& frame, const cv::Rect& rect, double pixels, Patch& out) {
  const cv::Size size = patch_size(rect, pixels);
  std::vector<int> xs, ys;
  sample_positions(rect.x, rect.width, size.width, xs);
  sample_positions(rect.y, rect.height, size.height, ys);
  const FullRangeTables& full = full_range_tables();
  const std::uint8_t* luma_full = full.luma.ptr<std::uint8_t>();
  const std::uint8_t* chroma_full = full.chroma.ptr<std::uint8_t>();
  const ImageView& l = frame.luma;
  const ChromaView& c = frame.chroma;
  cv::Mat ycrcb(size, CV_8UC3);
  for (int y = 0; y < size.height; ++y) {
    cv::Vec3b* row = ycrcb.ptr<cv::Vec3b>(y);
    for (int x = 0; x < size.width; ++x) {
      int luma = 0, cr = 0, cb = 0;
      for (int sy = 2 * y; sy < 2 * y + 2; ++sy)
        for (int sx = 2 * x; sx < 2 * x + 2; ++sx) {
          luma += l.data[static_cast<std::ptrdiff_t>(ys[sy]) * l.stride + xs[sx]];
          if (frame.has_chroma()) cr += c.v_at(xs[sx], ys[sy]), cb += c.u_at(xs[sx], ys[sy]);
        }
      row[x] = {luma_full[(luma + 2) / 4],
                frame.has_chroma() ? chroma_full[(cr + 2) / 4] : std::uint8_t{128},
                frame.has_chroma() ? chroma_full[(cb + 2) / 4] : std::uint8_t{128}};
    }
  }
  cv::cvtColor(ycrcb, out.bgr, cv::COLOR_YCrCb2BGR);
  out.rect = rect;
  out.kx = static_cast<double>(size.width) / rect.width;
  out.ky = static_cast<double>(size.height) / rect.height;
}

}  // namespace projtrack
