// Compiled with the solver's flags (granshock_fp: -march=native in a native build), so the
// macros below are those of the kernels' code. Data only: the program reads it from code
// compiled for any x86 CPU before it runs any of the solver's (apps/granshock/cpu_check.cpp).
#include "cases/build_info/build_description.hpp"

namespace granshock {

extern const char* const kCompiledCpuFeatures[] = {
#ifdef __SSE4_2__
    "sse4.2",
#endif
#ifdef __AVX__
    "avx",
#endif
#ifdef __AVX2__
    "avx2",
#endif
#ifdef __FMA__
    "fma",
#endif
#ifdef __BMI2__
    "bmi2",
#endif
#ifdef __AVX512F__
    "avx512f",
#endif
#ifdef __AVX512CD__
    "avx512cd",
#endif
#ifdef __AVX512DQ__
    "avx512dq",
#endif
#ifdef __AVX512BW__
    "avx512bw",
#endif
#ifdef __AVX512VL__
    "avx512vl",
#endif
    nullptr};

}  // namespace granshock
