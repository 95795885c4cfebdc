"""`granshock info` names the kernel paths and the bounds check this build has, and the keys
of every contact law and obstacle shape it lists (apps/granshock/build_info.cpp), each
with a type, a meaning and a default.

Usage: info_fields.py GRANSHOCK BOUNDS_CHECK(true|false) KERNEL_PATHS(host|device)"""
import json
import subprocess
import sys


def main():
    granshock, bounds_check, kernel_paths = sys.argv[1:4]
    info = json.loads(subprocess.run([granshock, "info"], check=True, capture_output=True,
                                     text=True).stdout)
    problems = []
    if info["bounds_check"] != (bounds_check == "true"):
        problems.append(f"bounds_check is {info['bounds_check']}, expected {bounds_check}")
    if info["kernel_paths"] != kernel_paths:
        problems.append(f"kernel_paths is {info['kernel_paths']}, expected {kernel_paths}")
    for choice, keys_of in (("contact model", "contact_law_keys"),
                            ("obstacle shape", "obstacle_shape_keys")):
        names = info["choices"][choice]
        if sorted(info[keys_of]) != sorted(names):
            problems.append(f"{keys_of} lists {sorted(info[keys_of])}, the choices {names}")
            continue
        for name in names:
            for key in info[keys_of][name]:
                missing = {"key", "type", "meaning", "default"} - set(key)
                if missing:
                    problems.append(f"{keys_of}.{name}: {key} lacks {sorted(missing)}")
    # The third law and the fourth shape, added with their own keys.
    if [k["key"] for k in info["contact_law_keys"].get("linear", [])] != ["contact.stiffness"]:
        problems.append("linear's keys are not [contact.stiffness]")
    if [k["key"] for k in info["obstacle_shape_keys"].get("square", [])] != \
            ["obstacle.side", "obstacle.rotation"]:
        problems.append("square's keys are not [obstacle.side, obstacle.rotation]")
    for p in problems:
        print("FAIL:", p)
    print("info: %d problems" % len(problems))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
