#include "adversarial.hpp"

#include <algorithm>
#include <cstdint>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace projtrack::synthetic {

namespace {

cv::Mat dots(int w, int h, double density, cv::RNG& rng) {
  cv::Mat u(h, w, CV_32F);
  rng.fill(u, cv::RNG::UNIFORM, 0.0, 1.0);
  cv::Mat out = u < density;  // 255 where true
  return out;
}

cv::Mat checker(int w, int h, int side, bool inverted) {
  cv::Mat out(h, w, CV_8U);
  for (int y = 0; y < h; ++y) {
    std::uint8_t* row = out.ptr<std::uint8_t>(y);
    for (int x = 0; x < w; ++x) row[x] = ((x / side + y / side + inverted) & 1) ? 255 : 0;
  }
  return out;
}

// Teeth: vertical 1-px walls on every other column, from the top to the last row but one, and a
// wall along the top row joining them; the phase and the side the spine is on alternate.
cv::Mat comb(int w, int h, int index) {
  cv::Mat out(h, w, CV_8U, cv::Scalar(0));
  const int phase = index & 1;
  for (int x = phase; x < w; x += 2) out.col(x).rowRange(0, std::max(0, h - 2)).setTo(255);
  out.row(0).setTo(255);
  if (index & 2) cv::flip(out, out, 0);
  return out;
}

// A perfect maze on cells of 3 px (a 2-px corridor and a 1-px wall), by randomised depth-first
// search from the centre.
cv::Mat maze(int w, int h, cv::RNG& rng) {
  cv::Mat out(h, w, CV_8U, cv::Scalar(255));
  const int cw = std::max(1, (w - 1) / 3), ch = std::max(1, (h - 1) / 3);
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(cw) * ch, 0);
  auto open = [&](int x0, int y0, int x1, int y1) {  // frame pixels, inclusive, clipped
    x0 = std::max(0, x0);
    y0 = std::max(0, y0);
    x1 = std::min(w - 1, x1);
    y1 = std::min(h - 1, y1);
    if (x0 <= x1 && y0 <= y1) out(cv::Rect(x0, y0, x1 - x0 + 1, y1 - y0 + 1)).setTo(0);
  };
  std::vector<int> stack{(ch / 2) * cw + cw / 2};
  seen[stack.back()] = 1;
  open(3 * (cw / 2) + 1, 3 * (ch / 2) + 1, 3 * (cw / 2) + 2, 3 * (ch / 2) + 2);
  static constexpr int kDx[4] = {1, -1, 0, 0}, kDy[4] = {0, 0, 1, -1};
  while (!stack.empty()) {
    const int c = stack.back(), cx = c % cw, cy = c / cw;
    int options[4], n = 0;
    for (int d = 0; d < 4; ++d) {
      const int nx = cx + kDx[d], ny = cy + kDy[d];
      if (nx >= 0 && ny >= 0 && nx < cw && ny < ch && !seen[ny * cw + nx]) options[n++] = d;
    }
    if (n == 0) {
      stack.pop_back();
      continue;
    }
    const int d = options[rng.uniform(0, n)];
    const int nx = cx + kDx[d], ny = cy + kDy[d];
    seen[ny * cw + nx] = 1;
    // The corridor from this cell into the next, through the wall between them.
    open(3 * std::min(cx, nx) + 1, 3 * std::min(cy, ny) + 1, 3 * std::max(cx, nx) + 2,
         3 * std::max(cy, ny) + 2);
    stack.push_back(ny * cw + nx);
  }
  return out;
}

// A square spiral of 1-px walls 3 px apart around the centre, mirrored on every other frame.
cv::Mat spiral(int w, int h, int index) {
  cv::Mat out(h, w, CV_8U, cv::Scalar(0));
  int x = w / 2, y = h / 2, len = 3;
  static constexpr int kDx[4] = {1, 0, -1, 0}, kDy[4] = {0, 1, 0, -1};
  for (int turn = 0; len < 2 * (w + h); ++turn, len += turn % 2 == 0 ? 3 : 0) {
    const int d = turn % 4;
    for (int i = 0; i < len; ++i) {
      if (x >= 0 && y >= 0 && x < w && y < h) out.at<std::uint8_t>(y, x) = 255;
      x += kDx[d];
      y += kDy[d];
    }
  }
  if (index & 1) cv::flip(out, out, 1);
  return out;
}

}  // namespace

cv::Mat adversarial_frame(Adversary kind, int width, int height, int index) {
  cv::RNG rng(0x9e3779b97f4a7c15ULL ^ (static_cast<std::uint64_t>(kind) << 32) ^
              static_cast<std::uint64_t>(index));
  switch (kind) {
    case Adversary::Noise: {
      cv::Mat out(height, width, CV_8U);
      rng.fill(out, cv::RNG::UNIFORM, 0, 256);
      return out;
    }
    case Adversary::Dots5:
      return dots(width, height, 0.05, rng);
    case Adversary::Dots15:
      return dots(width, height, 0.15, rng);
    case Adversary::Dots40:
      return dots(width, height, 0.40, rng);
    case Adversary::Blocks4: {
      cv::Mat small((height + 3) / 4, (width + 3) / 4, CV_8U), out;
      rng.fill(small, cv::RNG::UNIFORM, 0, 2);
      cv::resize(small * 255, out, cv::Size(small.cols * 4, small.rows * 4), 0, 0,
                 cv::INTER_NEAREST);
      return out(cv::Rect(0, 0, width, height)).clone();
    }
    case Adversary::Checker1:
      return checker(width, height, 1, index & 1);
    case Adversary::Checker8:
      return checker(width, height, 8, index & 1);
    case Adversary::Comb:
      return comb(width, height, index);
    case Adversary::Maze:
      return maze(width, height, rng);
    case Adversary::Spiral:
      return spiral(width, height, index);
  }
  return cv::Mat(height, width, CV_8U, cv::Scalar(0));
}

}  // namespace projtrack::synthetic
