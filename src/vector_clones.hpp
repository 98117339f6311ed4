// Hot loops compiled twice on x86-64, for the baseline and for AVX2, and chosen at load time by
// the CPU (GCC/Clang function multiversioning): twice the vector width where the CPU has it,
// with no build flag that would stop the plugin loading on an older CPU. Elsewhere: not inlined,
// which keeps the __restrict__ promises the vectoriser relies on.
#pragma once

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define PROJTRACK_VECTOR_CLONES [[gnu::target_clones("avx2", "default")]]
#else
#define PROJTRACK_VECTOR_CLONES [[gnu::noinline]]
#endif
