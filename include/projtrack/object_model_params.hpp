// How the appearance model finds, segments and learns the object from frame to frame
// (SilhouetteModel, src/appearance/silhouette_model.hpp): part of TrackerParams.
#pragma once

namespace projtrack {

struct ObjectModelParams {
  // The working scale makes the object about this many work pixels (whole pixels when smaller).
  double work_pixels = 6000;
  // The surroundings the colours are learned against: a ring this share of √area wide around
  // the silhouette (at least 8 px). Wide enough to take in the hand that holds the object.
  double ring = 0.5;
  // At the start, only the colours of the disc around the seed are the object's (its radius the
  // seed's depth in the first silhouette, at least this share of √area): a first silhouette may
  // take in part of the hand, the disc does not.
  double core = 0.2;
  int start_rounds = 3;  // rounds of segmenting and learning on the first frame
  // On the first frame the silhouette may reach this share of √area beyond the first one: across
  // a finger to the object's part on its other side.
  double start_reach = 0.25;
  // How fast the colours follow the object's: the share of one frame in the model. The model
  // learns every `learn_every` frames (at the rate of as many frames), which costs less.
  double learning_rate = 0.05;
  int learn_every = 3;
  // The silhouette may move this share of √area (at least 2 work px) beyond the last one moved
  // by the object's motion; the region searched is its box grown by `margin` of its larger side.
  double reach = 0.08;
  double margin = 0.15;
  // Before segmenting, the prior is moved to the object-like pixels within this share of √area
  // of it (mean shift): an object faster than its predicted motion.
  double window = 0.25;
  // Edge-bounded regions under this share of the expected area are taken or left whole.
  double small_region = 1.25;
  // A first silhouette that reaches the frame's border has taken in the arm that holds the
  // object (a held object is in the picture): it is cut where it is thinner than twice this share
  // of √area (an opening), and the pieces that then reach the border are dropped, unless the seed
  // is in one. The start learns the colours only where the silhouette is thicker than that, so
  // a thin band of the hand that joined it is not learned as the object's. 0: neither.
  double arm_cut = 0.1;
  // Started from the user's box, the object lies within the box grown by this share of its
  // sides: the first frame's silhouette is cut there (the hand that holds the object reaches
  // beyond the box, the object does not).
  double box_slack = 0.1;
};

}  // namespace projtrack
