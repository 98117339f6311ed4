#include "models/frame_evidence.hpp"

namespace projtrack {

const WorkImages& FrameEvidence::images(int scale) {
  if (images_scale_ != scale) {
    build_work_images(frame, scale, images_);
    images_scale_ = scale;
  }
  return images_;
}

}  // namespace projtrack
