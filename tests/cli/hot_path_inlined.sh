#!/usr/bin/env bash
# The helpers the force kernel calls per particle or per pair (the obstacle's contact
# test, the contact law, the pair loop, the tangential spring, the kernel's own helpers)
# must be inlined into it: GCC once outlined the cylinder's `touches`, at a large cost
# (docs/benchmarks.md, "Old against new: the restructuring, and inlining"). They are
# KOKKOS_FORCEINLINE_FUNCTION; this test fails when an out-of-line copy of one of them
# appears in the program. The same for the fused step's body (solver/fused_step.hpp), the
# force sum and the kicks it calls. Usage: hot_path_inlined.sh GRANSHOCK
set -euo pipefail
program=$1
pattern='::touches\(|::touches_polygon\(|::keeps_out\(|Model::normal<|Model::tangential<|::for_each_contact<|'
pattern+='ContactForceKernel<.*>::(velocity|obstacle_contact|claim_slot|find_slot|release_unused_slots|total|sum_contacts|friction)\(|'
pattern+='FusedStepKernel<.*>::operator\(\)|'
pattern+='tangential_force<|contact_point_velocity<|contact_torque<|half_kick<|half_spin_kick<'
# The per-contact lambda of sum_contacts is left out: with friction GCC outlines it (a
# call per touching pair, not per partner; it was so before the fused step as well).
outlined=$(nm -C "$program" | grep -E ' [tTwW] ' | grep -E "$pattern" | grep -v '::{lambda' || true)
if [[ -n $outlined ]]; then
  echo "out-of-line copies of force-kernel helpers (they must be inlined):" >&2
  echo "$outlined" | cut -c1-240 >&2
  exit 1
fi
count=$(nm -C "$program" | grep -cE ' [tTwW] .*ContactForceKernel<.*>::operator\(\)' || true)
[[ $count -gt 0 ]] || { echo "no force kernel found in $program: is it the granshock program?" >&2; exit 1; }
echo "force kernels: $count, outlined helpers: none"
