# Warnings are on for granshock's own targets (not for dependencies).
add_library(granshock_warnings INTERFACE)
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(granshock_warnings INTERFACE
    $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wshadow -Wnon-virtual-dtor -Wpedantic>)
endif()
# Identical results for any thread count need identical floating-point expressions:
# no fused multiply-add contraction that could differ between inlined copies.
add_library(granshock_fp INTERFACE)
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(granshock_fp INTERFACE $<$<COMPILE_LANGUAGE:CXX>:-ffp-contract=off>)
endif()
