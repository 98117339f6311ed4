// projtrack-bench's meta.json: the command, the machine, the parameters compared and the
// defaults, the scene model and how acquisition is judged.
#pragma once

#include "options.hpp"
#include "projtrack/params.hpp"

namespace projtrack::bench {

void write_meta(const Options& opt, const Params& compared, const Params& defaults, int scenes,
                int inconsistent);

}  // namespace projtrack::bench
