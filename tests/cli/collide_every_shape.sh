#!/usr/bin/env bash
# `granshock collide --shape NAME` for every obstacle shape `granshock info` names (so a
# shape added to core/variant_names.hpp is tested here without a change to this script):
# a steel particle at 1 m/s with the hooke law strikes the shape (its sizes collide's
# defaults, none given) on its upstream surface on the flow's line, the JSON names the
# shape, and e_eff and t_contact are the cylinder's within 3e-11 (the rounding bound
# derived in tests/physics/test_head_on_collision.cpp, CollideShape).
# Usage: collide_every_shape.sh GRANSHOCK
set -u
granshock=$1
failed=0
fail() { echo "FAIL: $*"; failed=1; }
info=$("$granshock" info) || { echo "FAIL: granshock info"; exit 1; }
shapes=$(python3 -c 'import json, sys; print(" ".join(json.load(sys.stdin)["choices"]["obstacle shape"]))' \
  <<<"$info") || { echo "FAIL: no obstacle shapes in granshock info"; exit 1; }
[ -n "$shapes" ] || { echo "FAIL: no obstacle shapes in granshock info"; exit 1; }
# At --phase 0.5: at 1 the step before contact ends at a gap of exactly 0, where rounding
# decides whether the contact starts there (a jump of hooke's e_eff: the test's comments).
collide() { "$granshock" collide --pair steel-obstacle --speed 1 --model hooke --phase 0.5 "$@" 2>/dev/null; }
cylinder=$(collide) || { echo "FAIL: collide against the default obstacle"; exit 1; }
for shape in $shapes; do
  out=$(collide --shape "$shape") || { fail "collide --shape $shape: $out"; continue; }
  python3 - "$shape" "$cylinder" "$out" <<'PY' || failed=1
import json, sys
shape, cylinder, out = sys.argv[1], json.loads(sys.argv[2]), json.loads(sys.argv[3])
o = out.get("obstacle", {})
print(f"{shape}: {o.get('struck')} at {o.get('struck_at')}, along {out['along']}, "
      f"e_eff {out['e_eff']:.15f} (cylinder {cylinder['e_eff']:.15f}), "
      f"t_contact {out['t_contact']:.6e} s (cylinder {cylinder['t_contact']:.6e} s)")
ok = True
def check(cond, what):
    global ok
    if not cond:
        print(f"FAIL: {shape}: {what}")
        ok = False
check(cylinder["obstacle"]["shape"] == "cylinder", "the default obstacle is not the cylinder")
check(o.get("shape") == shape, f"the JSON names the shape {o.get('shape')!r}")
check(out["along"] == "y", "not struck along the flow's line y")
check(abs(out["e_eff"] - cylinder["e_eff"]) <= 3e-11, "e_eff is not the cylinder's")
check(abs(out["t_contact"] / cylinder["t_contact"] - 1) <= 3e-11,
      "t_contact is not the cylinder's")
sys.exit(0 if ok else 1)
PY
done
[ $failed -eq 0 ] && echo PASS
exit $failed
