#!/bin/sh
# bench-alternate.sh: whether a change made meshpaint slower. Runs
# `meshpaint bench subdivide` (bunny level 4, armadillo level 3) and
# `meshpaint bench paint` with two builds, alternating old and new ROUNDS
# times in one sequence (so both meet the same host), and prints a markdown
# table of every run and the medians with their ratio.
#
#   scripts/bench-alternate.sh OLD_BUILD_DIR NEW_BUILD_DIR [ROUNDS] [WORK_DIR]
#
# Each build runs with its own libraries (LD_LIBRARY_PATH=BUILD/lib). A round
# takes about 8 minutes on 2 cores; run it on an otherwise idle machine.
set -eu
[ $# -ge 2 ] || { echo "usage: $0 OLD_BUILD_DIR NEW_BUILD_DIR [ROUNDS] [WORK_DIR]" >&2; exit 2; }
here=$(cd "$(dirname "$0")/.." && pwd)
old=$(cd "$1" && pwd); new=$(cd "$2" && pwd)
rounds=${3:-3}
work=${4:-/tmp/meshpaint-bench-alternate}
mkdir -p "$work"
cd "$here"
for r in $(seq 1 "$rounds"); do
  for side in old new; do
    build=$old; [ "$side" = new ] && build=$new
    run() { LD_LIBRARY_PATH="$build/lib" "$build/bin/meshpaint" "$@"; }
    run bench subdivide data/scans/bunny00.off --level 4 --repeats 21 --json > "$work/sub_bunny4_${side}_$r.json"
    run bench subdivide data/scans/armadillo.off --level 3 --repeats 21 --json > "$work/sub_arma3_${side}_$r.json"
    run bench paint --json > "$work/paint_${side}_$r.json"
  done
done
/usr/bin/python3 - "$work" <<'PY'
import glob, json, statistics, sys
work = sys.argv[1]
def runs(pattern):
    return [json.load(open(f)) for f in sorted(glob.glob(f"{work}/{pattern}"))]
rows = []
for name, key in [("subdivide bunny L4, kernels", "sub_bunny4"), ("subdivide armadillo L3, kernels", "sub_arma3")]:
    rows.append((name, [d["engine_ms"] for d in runs(f"{key}_old_*.json")], [d["engine_ms"] for d in runs(f"{key}_new_*.json")]))
paint = {side: runs(f"paint_{side}_*.json") for side in ("old", "new")}
meshes = [row["mesh"] for row in paint["old"][0]["brush"]]
for i, mesh in enumerate(meshes):
    for j, cover in enumerate(["1%", "10%", "50%"]):
        rows.append((f"sculpt step {mesh} {cover}", *[[d["brush"][i]["ms"][j] for d in paint[s]] for s in ("old", "new")]))
for i, mesh in enumerate(meshes):
    rows.append((f"smoothing pass {mesh}", *[[d["smoothing"][i]["meshpaint_ms"] for d in paint[s]] for s in ("old", "new")]))
for i, mesh in enumerate(meshes):
    rows.append((f"coarse dab {mesh} 50%", *[[d["coarse_edit"][i]["dab_ms"][2] for d in paint[s]] for s in ("old", "new")]))
print("| ms | old runs | old median | new runs | new median | new / old |")
print("|---|---|---|---|---|---|")
for name, o, n in rows:
    text = lambda v: " ".join(f"{x:.2f}" for x in v)
    mo, mn = statistics.median(o), statistics.median(n)
    print(f"| {name} | {text(o)} | {mo:.2f} | {text(n)} | {mn:.2f} | {mn / mo:.2f} |")
PY
