// The object models' factory, from the table's rows (include/projtrack/object_model_table.def):
// the one place that turns a kind into a model.
#include <array>

#include "models/object_model.hpp"

namespace projtrack {

Veto ObjectModel::veto(FrameEvidence&, const Features&, const Track&) { return {}; }

SilhouetteMask ObjectModel::silhouette(int, int) const { return {}; }

std::unique_ptr<ObjectModel> make_object_model(ObjectModelKind kind) {
  using Factory = std::unique_ptr<ObjectModel> (*)();
  static constexpr std::array<Factory, kObjectModelCount> kFactories = {
#define PROJTRACK_OBJECT_MODEL(id, nick, description) &make_object_model<ObjectModelKind::id>,
#include "projtrack/object_model_table.def"
#undef PROJTRACK_OBJECT_MODEL
  };
  const auto i = static_cast<std::size_t>(kind);
  return i < kFactories.size() ? kFactories[i]() : nullptr;
}

}  // namespace projtrack
