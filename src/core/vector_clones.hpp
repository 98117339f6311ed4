// Hot loops compiled twice on x86-64, for the baseline and for AVX2, and chosen at load time by
// the CPU (GCC/Clang function multiversioning): twice the vector width where the CPU has it,
// with no build flag that would stop the plugin loading on an older CPU. Elsewhere: not inlined,
// which keeps the __restrict__ promises the vectoriser relies on.
#pragma once

#include <cstddef>  // defines __GLIBC__ where glibc is the C library

// Needs ifunc: x86-64 ELF with glibc.
#if defined(__x86_64__) && defined(__GLIBC__) && defined(__has_attribute)
#if __has_attribute(target_clones)
#define PROJTRACK_VECTOR_CLONES [[gnu::target_clones("avx2", "default")]]
#endif
#endif
#ifndef PROJTRACK_VECTOR_CLONES
#define PROJTRACK_VECTOR_CLONES [[gnu::noinline]]
#endif
