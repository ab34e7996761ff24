#!/usr/bin/env bash
# Configure and build contrib/examples/plugin out of tree against this build
# tree's masonryConfig.cmake, load it with `Additional shared libraries`, and
# check load_multiplier = min(b/h, mu) for an overturning- and a
# sliding-governed block.
# Usage: plugin_example.sh PLUGIN_SOURCE MASONRY_BUILD_DIR MASONRY WORK_DIR
set -euo pipefail
source_dir=$1
masonry_build=$2
masonry=$3
work=$4

source "$(dirname "${BASH_SOURCE[0]}")/plugin_common.sh"
build_plugin "$source_dir" "$masonry_build" "$work" block_on_plane

check() { # name width height friction
  local name=$1 width=$2 height=$3 friction=$4
  cat >"$name.prm" <<PRM
set Additional shared libraries = $library
set Analysis                    = block on plane
set Output directory            = results-$name
subsection Block on plane
  set Width                = $width
  set Height               = $height
  set Depth                = 0.8
  set Density              = 2000
  set Friction coefficient = $friction
end
PRM
  "$masonry" "$name.prm"
  /usr/bin/python3 - "$name" "$width" "$height" "$friction" <<'PY'
import json, sys
name, b, h, mu = sys.argv[1], *map(float, sys.argv[2:])
s = json.load(open(f"results-{name}/summary.json"))
expected = min(b / h, mu)
mode = "overturning" if b / h <= mu else "sliding"
weight = 2000 * 9.81 * b * h * 0.8
ok = (s["status"] == "completed" and abs(s["load_multiplier"] - expected) < 1e-12
      and s["mode"] == mode and abs(s["weight"] - weight) < 1e-9 * weight
      and abs(s["overturning_multiplier"] - b / h) < 1e-12
      and abs(s["sliding_multiplier"] - mu) < 1e-12)
print(f"{name}: load_multiplier {s['load_multiplier']} expected {expected} "
      f"({mode}): {'ok' if ok else 'WRONG'}")
sys.exit(0 if ok else 1)
PY
}
check overturning 0.4 1.6 0.6 # b/h = 0.25 < mu
check sliding 1.2 1.0 0.45     # mu < b/h = 1.2

# a non-positive size is rejected with one error line naming the entry
sed 's/set Width                = 0.4/set Width                = -1/' overturning.prm >bad.prm
status=0
"$masonry" bad.prm 2>bad.err || status=$?
cat bad.err
if [[ $status -eq 0 ]] || ! grep -q "^masonry: error: bad.prm:5: entry 'Block on plane/Width': must be positive" bad.err; then
  echo "bad width: not rejected as expected"
  exit 1
fi
echo "bad width: rejected"
