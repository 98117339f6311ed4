#include "method_list.hpp"

#include <fstream>
#include <string_view>

#include "projtrack/method.hpp"

namespace projtrack::bench {

namespace {

const char* family_name(Family f) { return f == Family::Rays ? "rays" : "fill"; }

const char* trace_name(TraceKind t) {
  switch (t) {
    case TraceKind::Rays:
      return "rays";
    case TraceKind::RaysAndBlocks:
      return "rays-and-blocks";
    case TraceKind::FilledPixels:
      return "filled-pixels";
    case TraceKind::GridLines:
      return "grid-lines";
  }
  return "unknown";
}

// A CSV field in double quotes (a description holds commas), its quotes doubled.
std::string quoted(std::string_view text) {
  std::string q = "\"";
  for (char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + '"';
}

}  // namespace

void write_method_list(std::ostream& out) {
  out << "method,family,iterative,from_paper,trace,description\n";
  for (const MethodInfo& m : kMethods)
    out << m.nick << ',' << family_name(m.family) << ',' << m.iterative << ',' << m.from_paper
        << ',' << trace_name(m.trace) << ',' << quoted(m.description) << '\n';
}

bool write_method_list(const std::string& dir) {
  std::ofstream out(dir + "/methods.csv");
  write_method_list(out);
  return static_cast<bool>(out);
}

}  // namespace projtrack::bench
