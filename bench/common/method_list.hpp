// The table of methods as CSV, for the Python report and tests: they read it (`--list-methods`,
// or methods.csv beside the results) instead of keeping their own list of names.
#pragma once

#include <ostream>
#include <string>

namespace projtrack::bench {

// A header and one row per method, in the table's order:
// method,family,iterative,from_paper,trace,description (family: rays or fill; trace: rays,
// rays-and-blocks, filled-pixels or grid-lines; iterative and from_paper: 0 or 1).
void write_method_list(std::ostream& out);
// The same into DIR/methods.csv; false when it cannot be written.
bool write_method_list(const std::string& dir);

}  // namespace projtrack::bench
