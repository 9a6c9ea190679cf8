// The CPU engine's hot functions compiled twice, for baseline x86-64 and for x86-64-v3 (AVX2,
// FMA, BMI2); the dynamic loader picks the second where the CPU has it (GCC's function
// multiversioning, an ifunc): the reference still runs on any x86-64 and is faster where it can.
// `flatten` inlines everything such a function calls into each copy: without it GCC keeps the
// callees out of line, compiled once for baseline x86-64, and the x86-64-v3 copy is only a wrapper
// around them. A file that defines such functions is compiled with -ffp-contract=off
// (cpu_ref/CMakeLists.txt): neither copy fuses a multiply-add, so both compute the same bits.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define TP_ISA_CLONES __attribute__((flatten, target_clones("default", "arch=x86-64-v3")))
#else
#define TP_ISA_CLONES
#endif
