#!/usr/bin/env bash
# Device code lives in kernels/ only: the CUDA build compiles granshock_kernels alone
# (docs/cuda.md, "CI"), so a KOKKOS_LAMBDA, KOKKOS_FUNCTION or parallel_* pattern anywhere
# else would be compiled for the host only. Also a word in a comment: the check cannot
# tell a comment from code, and a comment can say "kernel launch" instead.
# Usage: check_device_code.sh [ROOT]; lists the offending files and exits 1, else 0.
set -euo pipefail
cd "${1:-$(dirname "$0")/..}"
if grep -rlE "KOKKOS_LAMBDA|KOKKOS_INLINE_FUNCTION|KOKKOS_FUNCTION|\bparallel_(for|reduce|scan)\b" \
  core models io analysis cases apps parallel tests; then
  echo "check_device_code.sh: the sources above hold device code outside kernels/; move it to" \
    "kernels/ or build their targets for CUDA in .ci/run too" >&2
  exit 1
fi
