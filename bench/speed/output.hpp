// What projtrack-speed writes: speed.csv (section, clip, resolution, what, key, value; one row
// per measurement) and meta.json (the machine and the settings measured with).
#pragma once

#include <cstdio>
#include <string>

#include "clip.hpp"

namespace projtrack::bench {

// The element's own default method, read from its property by main().
extern std::string kDefaultMethod;
// The element with every property at its default (the flow model): what users run.
extern const std::string kElementDefault;

// speed.csv, open for the whole run (main() opens and closes it).
extern std::FILE* csv;

// One row of speed.csv; `c` null for a row of no clip.
void row(const std::string& section, const Clip* c, const std::string& what, const std::string& key,
         double value);

void write_meta(const std::string& dir, const std::string& measured);

}  // namespace projtrack::bench
