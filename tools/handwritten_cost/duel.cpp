// Timing and counting one routine against the library's: see duel.hpp.
#include "duel.hpp"

#include <algorithm>
#include <chrono>
#include <vector>

#include "alloc_count.hpp"

namespace projtrack::handwritten {
namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

double batch_us(const std::function<void()>& f, int calls) {
  const auto t0 = Clock::now();
  for (int i = 0; i < calls; ++i) f();
  return std::chrono::duration<double, std::micro>(Clock::now() - t0).count() / calls;
}

// Allocations per call once the buffers a first call sizes exist.
double allocations_per_call(const std::function<void()>& f, int calls) {
  const long before = bench::allocations.load();
  for (int i = 0; i < calls; ++i) f();
  return static_cast<double>(bench::allocations.load() - before) / calls;
}

// CSV-safe: the text fields hold commas, never quotes.
std::string quoted(const std::string& s) { return "\"" + s + "\""; }

}  // namespace

Duel duel(const std::function<void()>& ours, const std::function<void()>& library, int rounds,
          int calls) {
  for (int i = 0; i < 3; ++i) {
    ours();
    library();
  }
  Duel d;
  d.ours.allocs = allocations_per_call(ours, calls);
  d.library.allocs = allocations_per_call(library, calls);
  std::vector<double> a, b;
  for (int r = 0; r < rounds; ++r) {
    if (r % 2) {
      b.push_back(batch_us(library, calls));
      a.push_back(batch_us(ours, calls));
    } else {
      a.push_back(batch_us(ours, calls));
      b.push_back(batch_us(library, calls));
    }
  }
  d.ours.us = median(a);
  d.library.us = median(b);
  return d;
}

void write_header(std::FILE* out) {
  std::fprintf(out,
               "routine,where,library,input,ours_us,ours_allocs,library_us,library_allocs,"
               "same,note\n");
}

void write_row(std::FILE* out, const Row& r, const Duel& d) {
  std::fprintf(out, "%s,%s,%s,%s,%.4g,%.3g,%.4g,%.3g,%s,\n", quoted(r.routine).c_str(),
               quoted(r.where).c_str(), quoted(r.library).c_str(), quoted(r.input).c_str(),
               d.ours.us, d.ours.allocs, d.library.us, d.library.allocs, quoted(r.same).c_str());
  std::fflush(out);
}

void write_library_only(std::FILE* out, const Row& r, const Cost& library, const std::string& why) {
  std::fprintf(out, "%s,%s,%s,%s,,,%.4g,%.3g,%s,%s\n", quoted(r.routine).c_str(),
               quoted(r.where).c_str(), quoted(r.library).c_str(), quoted(r.input).c_str(),
               library.us, library.allocs, quoted(r.same).c_str(), quoted(why).c_str());
  std::fflush(out);
}

}  // namespace projtrack::handwritten
