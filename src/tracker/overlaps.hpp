// Where the silhouettes of two objects of one frame meet (MultiTracker): the frame pixels both
// claim, sampled at the finer of their scales.
#pragma once

#include "core/frame_pixels.hpp"
#include "projtrack/silhouette_mask.hpp"

namespace projtrack {

// The frame pixels inside both `a` and `b` (empty when they do not meet, or either is empty).
FramePixels shared_pixels(const SilhouetteMask& a, const SilhouetteMask& b);
// The frame area `s` covers, px².
double silhouette_area(const SilhouetteMask& s);
// `s`'s rectangle in frame px, clipped to the frame.
cv::Rect frame_rect(const SilhouetteMask& s);
// Whether `s`'s rectangle covers at least half of `box` (frame px).
bool covers_half_of(const SilhouetteMask& s, const Rect& box);

}  // namespace projtrack
