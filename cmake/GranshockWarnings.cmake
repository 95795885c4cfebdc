# Warnings are on for granshock's own targets (not for dependencies).
#
# In a CUDA build with nvcc (Kokkos' nvcc_wrapper is the C++ compiler, or Kokkos'
# launcher routes compiles through it), every source is compiled by nvcc and the host
# part by g++: nvcc_wrapper hands flags it does not know to g++ (-Xcompiler). The
# compiler id is then still GNU. -Wpedantic is left out there: g++ compiles nvcc's
# generated code, whose `# 123 "file"` line markers are a GNU extension, and warns on
# each of them (27 000 warnings for a 2-line Kokkos program; nvcc_wrapper silently drops
# the flag anyway).
set(GRANSHOCK_NVCC OFF)
if(Kokkos_ENABLE_CUDA AND Kokkos_CXX_COMPILER_ID STREQUAL "NVIDIA")
  set(GRANSHOCK_NVCC ON)
endif()

add_library(granshock_warnings INTERFACE)
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(granshock_warnings INTERFACE
    $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wshadow -Wnon-virtual-dtor>)
  if(NOT GRANSHOCK_NVCC)
    target_compile_options(granshock_warnings INTERFACE $<$<COMPILE_LANGUAGE:CXX>:-Wpedantic>)
  endif()
endif()

# Identical results for any thread count need identical floating-point expressions:
# no fused multiply-add contraction that could differ between inlined copies.
# With nvcc the same holds for device code: --fmad=false (nvcc contracts by default),
# which also keeps GPU arithmetic bitwise comparable with the host backends
# (tests/unit/test_backend_agreement.cpp compares the default space with Serial).
# Two flags for the force kernel's code, each worth a measured factor in the fused step
# (docs/benchmarks.md, "What changed, and what each change bought").
# -fno-math-errno: sqrt compiles to one instruction instead of a branch to a library
#   call that sets errno for negative arguments; the call clobbers every vector register,
#   so a particle's force stayed in memory around its contact loop. Results are the same:
#   the instruction and the library both round correctly.
# -fno-tree-loop-vectorize: GCC vectorised the 2- or 3-iteration loops over a vector's
#   components with 16-byte loads of values just stored as two 8-byte halves, a
#   store-forwarding stall per particle.
add_library(granshock_fp INTERFACE)
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(granshock_fp INTERFACE
    $<$<COMPILE_LANGUAGE:CXX>:-ffp-contract=off -fno-math-errno>)
endif()
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  target_compile_options(granshock_fp INTERFACE $<$<COMPILE_LANGUAGE:CXX>:-fno-tree-loop-vectorize>)
endif()
# GRANSHOCK_NATIVE: with -ffp-contract=off above, the instructions change but not the
# arithmetic, so a native build gives bitwise the results of a portable one
# (tests/reference/check_bitwise.sh passes with either).
if(GRANSHOCK_NATIVE AND NOT GRANSHOCK_NVCC AND CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  include(CheckCXXCompilerFlag)
  check_cxx_compiler_flag(-march=native GRANSHOCK_HAS_MARCH_NATIVE)
  if(GRANSHOCK_HAS_MARCH_NATIVE)
    target_compile_options(granshock_fp INTERFACE $<$<COMPILE_LANGUAGE:CXX>:-march=native>)
  endif()
endif()
# What the build says of its instruction set (summary.json "build", granshock --version):
# native and, where GCC tells, the CPU it stands for.
set(GRANSHOCK_MARCH "default")
if(GRANSHOCK_HAS_MARCH_NATIVE AND GRANSHOCK_NATIVE AND NOT GRANSHOCK_NVCC)
  set(GRANSHOCK_MARCH "native")
  execute_process(COMMAND ${CMAKE_CXX_COMPILER} -march=native -Q --help=target
                  OUTPUT_VARIABLE target_help ERROR_QUIET)
  if(target_help MATCHES "\n[ \t]*-march=[ \t]*([A-Za-z0-9_.-]+)")
    set(GRANSHOCK_MARCH "native (${CMAKE_MATCH_1})")
  endif()
endif()
if(GRANSHOCK_NVCC)
  target_compile_options(granshock_fp INTERFACE $<$<COMPILE_LANGUAGE:CXX>:--fmad=false>)
endif()
