// The object models' factory, from the table's rows (include/projtrack/object_model_table.def):
// the one place that turns a kind into a model.
#include "models/object_model.hpp"

namespace projtrack {

Veto ObjectModel::veto(FrameEvidence&, const Features&, const Track&) { return {}; }

SilhouetteMask ObjectModel::silhouette(int, int) const { return {}; }

double ObjectModel::explains(const FramePixels&) const { return -HUGE_VAL; }

Observation ObjectModel::give_up(const FramePixels&, const Observation& o) { return o; }

std::unique_ptr<ObjectModel> make_object_model(ObjectModelKind kind) {
  switch (kind) {
#define PROJTRACK_OBJECT_MODEL(id, value, nick, description) \
  case ObjectModelKind::id:                                  \
    return make_object_model<ObjectModelKind::id>();
#include "projtrack/object_model_table.def"
#undef PROJTRACK_OBJECT_MODEL
  }
  return nullptr;  // an integer that is no row's: the caller validates it first
}

}  // namespace projtrack
