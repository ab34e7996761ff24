#!/usr/bin/env bash
# Build contrib/examples/postprocessor (the output `hinges csv`) out of tree
# against this build tree, load it with `Additional shared libraries` into
# the settling arch of prm/examples/arch-vertical-settlement.prm and check
# that it writes its file: three hinges (the classical mechanism of an arch
# whose springing settles), the interfaces the crack list calls hinges, and
# no file of the postprocessors that are not listed.
# Usage: postprocessor_plugin.sh PLUGIN_SOURCE MASONRY_BUILD_DIR MASONRY WORK_DIR EXAMPLE_PRM
set -euo pipefail
source_dir=$1
masonry_build=$2
masonry=$3
work=$4
example=$5

source "$(dirname "${BASH_SOURCE[0]}")/plugin_common.sh"
build_plugin "$source_dir" "$masonry_build" "$work" hinges_csv

write_prm() { # name list [file name]
  cp "$example" "$1.prm"
  cat >>"$1.prm" <<PRM
set Additional shared libraries = $library
set Output directory            = results-$1
subsection Settlement
  set Write picture = false
end
subsection Postprocess
  subsection Rigid blocks
    set List of postprocessors = $2
    subsection Hinges csv
      set File name = ${3:-hinges.csv}
    end
  end
end
PRM
}

write_prm listed "cracks, hinges csv"
expect_documented "$masonry" listed.prm "hinges csv" hinges.csv
"$masonry" listed.prm >listed.log

write_prm renamed "hinges csv" my_hinges.csv
"$masonry" renamed.prm >renamed.log

/usr/bin/python3 - <<'PY'
import csv, json, sys
ok = True
def check(cond, what):
    global ok
    print(("OK " if cond else "FAILED ") + what)
    ok = ok and cond
s = json.load(open("results-listed/summary.json"))
rows = list(csv.DictReader(open("results-listed/hinges.csv")))
check(len(rows) == 3, f"three hinges in hinges.csv (got {len(rows)})")
hinges = sorted(c["interface"] for c in s["cracks"] if c["type"] == "hinge")
check(sorted(int(r["interface"]) for r in rows) == hinges,
      "the hinges of the crack list")
check(all(float(r["max_opening_m"]) > 0 and float(r["relative_rotation_rad"]) > 0
          for r in rows), "every hinge opens and rotates")
check(sorted(s["files"]) == ["hinges.csv", "log.txt", "parameters.prm", "summary.json"],
      "only the listed outputs: " + ", ".join(sorted(s["files"])))
r = json.load(open("results-renamed/summary.json"))
check("my_hinges.csv" in r["files"] and "cracks" not in r,
      "File name of the plugin's subsection is used; cracks not listed, not run")
sys.exit(0 if ok else 1)
PY
