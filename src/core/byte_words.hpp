// Eight bytes of a mask or an edge map at a time: finding set bytes in a 64-bit word.
#pragma once

#include <cstdint>
#include <cstring>

namespace projtrack {

inline std::uint64_t load8(const std::uint8_t* p) {
  std::uint64_t v;
  std::memcpy(&v, p, 8);
  return v;
}

// High bit of every non-zero byte of v set, every other bit clear.
inline std::uint64_t nonzero_bytes(std::uint64_t v) {
  constexpr std::uint64_t kLow7 = 0x7F7F7F7F7F7F7F7Full;
  return (((v & kLow7) + kLow7) | v) & ~kLow7;
}

// The index in memory order (0 to 7) of the first byte whose high bit is set in `bits` (not 0).
inline int first_byte(std::uint64_t bits) {
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
  return __builtin_clzll(bits) / 8;
#else
  return __builtin_ctzll(bits) / 8;
#endif
}

}  // namespace projtrack
