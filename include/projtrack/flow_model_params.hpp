// How the flow model follows the whole object (ObjectModelKind::Flow): its last silhouette
// carried along the picture's dense motion, then cut from its surroundings by colour and motion
// (src/segmentation/flow_segmenter.hpp). Part of TrackerParams; every length is a share of the
// object's √area, so the same values hold for a small and a large object.
#pragma once

#include <string>

namespace projtrack {

struct FlowModelParams {
  // A start reads the whole frame at the working scale that makes it about this many work pixels
  // (an integer scale: 854×480 and 640×480 are read at half size, 1080p at a fifth).
  double work_pixels = 100000;
  // The object is then followed at its own scale: the integer scale that makes it about this many
  // work pixels (its area at the start). Its work — its motion, its cut, its colours — is within
  // a few times its area around it, so a large object costs no more than a small one, and a
  // small one in a large frame no more than in a small one. davis-dev (the bench's quick loop,
  // J from mask / box / click): 10 000 px 69.3 / 61.1 / 57.2, 14 000 69.1 / 61.8 / 59.0,
  // 20 000 69.1 / 62.3 / 59.3, at 2.6-5.4, 3.1-5.6 and 3.1-6.7 M work units a median frame.
  double object_pixels = 14000;
  // The picture's motion is measured at the coarsest level of DIS's pyramid (no coarser than its
  // ultrafast preset's, a quarter of the working frame) at which the object still spans this
  // many pixels (√area): a smaller object is a speck there and is carried along with what
  // surrounds it, and a finer field follows a fast or many-limbed one (davis-dev: 8 → 32 took J
  // from the first mask 66.2 → 69.9, at about 1.3 × the cost a frame). 0: always the preset's
  // level.
  double flow_span = 32;
  // A start from a box cuts the box at about this many cells, whatever the frame's or the box's
  // size (segmentation/box_start): a cut's grain is relative to the box, and its work is the
  // cells'. 4000 (about 3 ms, 2M work units): 3000 to 8000 measured alike on davis-dev's first
  // silhouettes, and the work grows faster than the cells.
  double box_pixels = 4000;
  // How far the object may have moved beyond what the flow says: the carried silhouette is
  // blurred this share of √area wide before it becomes the prior.
  double prior_spread = 0.2;
  // The prior's confidence is kept within [floor, 1 - floor]: colour and motion can overrule it.
  double prior_floor = 0.02;
  // How fast the colours follow the object's (the share of one frame), and the share of the
  // first frame's colours in the evidence (they anchor it against drift).
  double learning_rate = 0.05;
  double first_share = 0.5;
  // When the first silhouette is outlined (a mask, or the cut within a box), the colours near
  // each part of the object count too (segmentation/local_colours): its box cut into
  // `local_colour_cells` × as many cells, each with its own object and surroundings colours, at
  // this weight beside the frame-wide ones. 0: none. A start from a point does not learn them.
  double local_colour_weight = 0.5;
  int local_colour_cells = 4;
  // The followed surroundings' colours are those of a ring this share of √area wide around the
  // silhouette (the first frame's are the whole rest of the frame): what the object must be told
  // from is what lies next to it.
  double colour_ring = 0.25;
  // Motion evidence: the surroundings' motion is read in a ring this share of √area wide; a
  // pixel's evidence is at most this many nats either way; none when the object and its
  // surroundings move less than `min_separation` work px a frame apart.
  double motion_ring = 0.25;
  double motion_weight = 2.0;
  double min_separation = 1.0;
  // The object's fullest recent silhouette is remembered, moved with the object's own motion
  // (not each pixel's: an occluder's flow would carry the hidden part away), and stands in the
  // prior at this weight: a part that passes behind a pole is found again when it comes out. It
  // is replaced when a silhouette of at least `memory_refresh` × the fullest recent area is seen;
  // that area fades by `memory_fade` a frame (an object moving away shrinks for good).
  double memory_weight = 0.3;
  double memory_refresh = 0.8;
  double memory_fade = 0.02;
  // A piece of the new silhouette is kept when it holds at least this share of the prior that
  // the best piece holds: a region of the object's colours apart from it is not the object.
  double keep_share = 0.1;
  // From a point (no local colours to judge them), a pixel new to the object — outside the
  // carried silhouette eroded by `new_core` × √area — whose colour the first frame's model
  // holds for the surroundings' gets `new_motion_share` of its motion evidence: a hand that
  // moves with the held object it was not part of does not join it by its motion alone, while a
  // limb of the object's colours still does. 1: motion counts alike everywhere.
  double new_motion_share = 0.5;
  double new_core = 0.05;
};

// Empty when every member is in range (work_pixels at least 1000, object_pixels at least 100,
// box_pixels in [100, 1e7], prior_floor in (0, 0.5), the shares, rates and weights in [0, 1] but
// motion_weight in [0, 50], local_colour_cells in [1, 16], memory_fade below 1, flow_span and the
// widths at least 0, new_motion_share and new_core in [0, 1]); otherwise which one is not, and
// its range.
std::string validate(const FlowModelParams& p);

}  // namespace projtrack
