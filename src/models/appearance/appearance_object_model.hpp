// The appearance model (ObjectModelKind::Appearance): the object's silhouette and its colours
// against its surroundings'. On every frame it finds the whole object near its last silhouette
// moved by its motion — through prints and highlights, without the hand that holds it — from its
// colours, its edges and that last silhouette (appearance/silhouette_model); a new object is
// found by acquisition/'s finder. The estimator runs on the silhouette's outline.
#pragma once

#include "models/appearance/appearance_memory.hpp"
#include "models/object_model.hpp"

namespace projtrack {

class AppearanceObjectModel final : public ObjectModel {
 public:
  bool tracking() const override { return m_.object.tracking(); }
  Observation start(FrameEvidence& ev, const StartRequest& request, const Track& track) override;
  Observation follow(FrameEvidence& ev, const Track& track) override;
  Veto veto(FrameEvidence& ev, const Features& f, const Track& track) override;
  void settle(Verdict verdict) override;
  bool rescale(double sx, double sy, int width, int height) override;
  bool relearn() override;
  void forget(Forget what) override;
  SilhouetteMask silhouette(int frame_width, int frame_height) const override;
  bool drops_unsteady() const override { return true; }

 private:
  // The frame as the model reads it: a dim one stretched to a normal exposure (Exposure). The
  // model's colours are learned under it, so it is measured only while no object is known and
  // held while one is: the frame's range changes with what moves through it (a bright object
  // that leaves a dim room), and the model follows slow changes of the light by itself.
  ColorView as_read(const ColorView& raw, const TrackerParams& tp);

  enum class Step { None, Start, Continuation, Follow };
  AppearanceMemory m_;
  Mask first_, silhouette_;     // this frame's: the finder's first silhouette; the model's
  Step step_ = Step::None;      // what this frame's observation came from
  ObjectModelParams learning_;  // this frame's, for settle()
};

}  // namespace projtrack
