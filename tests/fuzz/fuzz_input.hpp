// What the fuzz targets share: the reader of their input, and how a broken promise ends a run.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace projtrack::fuzz {

// Reads the input front to back; past the end it yields zeros.
class Input {
 public:
  Input(const std::uint8_t* d, std::size_t n) : d_(d), n_(n) {}
  std::uint8_t byte() { return i_ < n_ ? d_[i_++] : 0; }
  int in(int lo, int hi) { return lo + static_cast<int>(u16() % (hi - lo + 1)); }
  std::uint16_t u16() { return static_cast<std::uint16_t>(byte() | byte() << 8); }
  std::size_t left() const { return i_ < n_ ? n_ - i_ : 0; }

 private:
  const std::uint8_t* d_;
  std::size_t n_, i_ = 0;
};

// A promise of the API broken: libFuzzer saves the input that did it.
inline void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz: broken promise: %s\n", what);
    std::abort();
  }
}

}  // namespace projtrack::fuzz
