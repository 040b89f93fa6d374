#!/usr/bin/env python3
"""Why a crate outside the workspace (examples/own-kernel) would compile rust-gpu's compiler again
instead of reusing the workspace's build of it: the first place where the two build graphs give
rustc_codegen_spirv a different unit (features, profile, or a dependency's).

    python3 tools/compiler_units.py WORKSPACE_UNIT_GRAPH.json OTHER_UNIT_GRAPH.json

Each graph comes from `cargo ... --unit-graph -Z unstable-options` (the pinned nightly takes -Z).
A typical cause: a crate whose build script runs once for both the host and the target side in one
graph (its features agree there) but only for the host side in the other, which changes its profile.
Standard library only."""
import json
import sys

COMPILER = "rustc_codegen_spirv"


def signatures(path):
    units = json.load(open(path))["units"]
    memo = {}

    def sig(i):
        if i not in memo:
            u = units[i]
            # The profile's name (dev or test) does not reach the compiled unit; its settings do.
            profile = {k: v for k, v in u["profile"].items() if k != "name"}
            deps = tuple(sorted(sig(d["index"]) for d in u["dependencies"]))
            memo[i] = (u["pkg_id"].rsplit("#", 1)[-1], u["target"]["name"], u["mode"],
                       tuple(sorted(u["features"])), json.dumps(profile, sort_keys=True), deps)
        return memo[i]

    return [sig(i) for i, u in enumerate(units) if u["target"]["name"] == COMPILER]


def first_difference(a, b, path=()):
    """The chain of units down to the first one that differs in itself, not only in a dependency."""
    here = path + (f"{a[0]} ({a[1]}, {a[2]})",)
    if a[3] != b[3]:
        return here, f"features {list(a[3])} against {list(b[3])}"
    if a[4] != b[4]:
        return here, f"profile {a[4]} against {b[4]}"
    deps_a = {d[:3]: d for d in a[5]}
    deps_b = {d[:3]: d for d in b[5]}
    for key in sorted(set(deps_a) ^ set(deps_b)):
        side = "only the first" if key in deps_a else "only the second"
        return here, f"dependency {key[0]} ({key[1]}, {key[2]}) in {side}"
    for key in sorted(deps_a):
        if deps_a[key] != deps_b[key]:
            return first_difference(deps_a[key], deps_b[key], here)
    return here, "no difference found"


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    a, b = signatures(sys.argv[1]), signatures(sys.argv[2])
    if len(a) != 1 or len(b) != 1:
        sys.exit(f"expected one {COMPILER} unit in each graph, found {len(a)} and {len(b)}")
    if a[0] == b[0]:
        print(f"{COMPILER}: the same unit in both graphs (it is reused)")
        return
    chain, what = first_difference(a[0], b[0])
    print(f"{COMPILER}: a different unit; the first difference:")
    for depth, unit in enumerate(chain):
        print("  " * (depth + 1) + unit)
    print("  " * (len(chain) + 1) + what)
    sys.exit(1)


if __name__ == "__main__":
    main()
