#!/usr/bin/python3
"""The device check's comparison (apps/bench/gpu_check_compare.py) judges what it says it
judges (docs/cuda.md, "The device check"): a digest against itself is bitwise; field sums
that differ by round-off pass and by more fail; a changed state passes on statistics
(counts and KE within 2 %, each field total within 3 sqrt(2) of its standard deviation
over the reference's seeds) and fails past them; e_eff must agree in every case; missing
or reshaped sums, or a reference without other seeds, fail.
Usage: gpu_check_compare_judges.py REPO"""
import copy
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(sys.argv[1]) / "apps" / "bench"))
import gpu_check_compare as g  # noqa: E402

REF = {
    "state": "0" * 32, "particles_final": 30000, "inserted": 40000, "deleted": 10000,
    "kinetic_energy": 0.5, "contacts": 100, "list_builds": 50,
    "particle_steps_per_second": 1e8,
    "e_eff": {"steel-steel at_inflow_speed": 0.52, "steel-obstacle at_inflow_speed": None},
    "field_totals": {
        "fields/grid/sums": {"sum": [1e6, -3.0, 1e6, 1e4, -600.0, 9e5, 2e6, 1.0, 2e6, 1e4,
                                     2e3, 9e5, 0.01, -8e-4, -8e-4, 0.01],
                             "abs": [1e6, 5e3, 1e6, 1e4, 3e3, 9e5, 2e6, 6e3, 2e6, 1e4,
                                     4e3, 9e5, 0.01, 2e-3, 2e-3, 0.01]}},
}
# Two other seeds 1 % above and below every total: a standard deviation of 1 % of it, so a
# difference of 3 sqrt(2) % = 4.24 % is the limit.
SUMS = REF["field_totals"]["fields/grid/sums"]["sum"]
REF["other_seeds"] = [{"fields/grid/sums": [v * 1.01 for v in SUMS]},
                      {"fields/grid/sums": [v * 0.99 for v in SUMS]}]
failures = []


def expect(name, now, status, words):
    got, text = g.compare(REF, now)
    if got != status or words not in text:
        failures.append(f"{name}: expected {status} with '{words}', got {got}: {text}")


def changed(**kw):
    now = copy.deepcopy(REF)
    for k, v in kw.items():
        now[k] = v
    return now


def with_field(k, factor, state=None):
    now = copy.deepcopy(REF)
    if state:
        now["state"] = state
    now["field_totals"]["fields/grid/sums"]["sum"][k] *= factor
    return now


expect("itself", REF, "ok", "bitwise")
# Round-off in the sums (the device adds them in another order) passes, more fails; the
# small virial terms are judged against their own absolute sums, not the counts'.
expect("round-off in a sum", with_field(0, 1 + 1e-12), "ok", "bitwise")
expect("a virial term off by 1e-6", with_field(13, 1 + 1e-6), "FAIL", "grid Wxy")
expect("KE past round-off", changed(kinetic_energy=0.5 * (1 + 1e-7)), "FAIL", "past round-off")
expect("a count off by one", changed(particles_final=30001), "FAIL", "past round-off")
# Another state: statistics.
other = "1" * 32
expect("statistics within", changed(state=other, particles_final=30300,
                                    kinetic_energy=0.5 * 1.015), "ok", "within")
expect("counts past 2 %", changed(state=other, inserted=40900), "FAIL", "PAST")
expect("KE past 2 %", changed(state=other, kinetic_energy=0.5 * 1.03), "FAIL", "PAST")
expect("a field past 3 sqrt(2) sd", with_field(2, 1.045, other), "FAIL", "grid cy[0]")
expect("a field within 3 sqrt(2) sd", with_field(2, 1.04, other), "ok", "within")
expect("a virial term past", with_field(12, 0.95, other), "FAIL", "grid Wxx")
expect("a virial term within", with_field(12, 0.96, other), "ok", "within")
unseeded = copy.deepcopy(REF)
del unseeded["other_seeds"]
got, text = g.compare(unseeded, changed(state=other))
if got != "FAIL" or "record it again" not in text:
    failures.append(f"no other seeds: expected FAIL naming the record, got {got}: {text}")
# e_eff: in both cases, to 1e-9; null only where the host's is null.
e = copy.deepcopy(REF["e_eff"])
e["steel-steel at_inflow_speed"] *= 1 + 1e-8
expect("e_eff off, same state", changed(e_eff=e), "FAIL", "e_eff differs")
expect("e_eff off, other state", changed(state=other, e_eff=e), "FAIL", "e_eff differs")
e = copy.deepcopy(REF["e_eff"])
e["steel-obstacle at_inflow_speed"] = 0.4
expect("e_eff measured where the host's was not", changed(e_eff=e), "FAIL", "e_eff differs")
expect("e_eff missing", changed(e_eff={}), "FAIL", "e_eff missing")
now = copy.deepcopy(REF)
del now["field_totals"]["fields/grid/sums"]
expect("sums missing", now, "FAIL", "missing or reshaped")
now = copy.deepcopy(REF)
now["field_totals"]["fields/grid/sums"]["sum"].pop()
expect("sums reshaped", now, "FAIL", "missing or reshaped")

if failures:
    print("\n".join(failures))
    sys.exit(1)
print("gpu_check_compare: every case judged as documented")
