#!/usr/bin/env bash
# Build contrib/examples/wallette_postprocessor (the output `peak csv`) out of
# tree against this build tree, load it with `Additional shared libraries`
# into a wallette of two stack-bonded bricks pulled apart across the bed
# joint, and check its file against curve.csv of the same run: the step,
# strain and stress of the largest stress, the joint damage at the end (the
# law's state through the public model view), and that the peak lies below
# the joint's tensile strength (0.2 MPa) but close to it. The postprocessor
# is documented by --print-parameters, its `File name' is used, and
# unlisted postprocessors do not run.
# Usage: wallette_postprocessor_plugin.sh PLUGIN_SOURCE MASONRY_BUILD_DIR MASONRY WORK_DIR
set -euo pipefail
source_dir=$1
masonry_build=$2
masonry=$3
work=$4

source "$(dirname "${BASH_SOURCE[0]}")/plugin_common.sh"
build_plugin "$source_dir" "$masonry_build" "$work" peak_csv

write_prm() { # name list [file name]
  cat >"$1.prm" <<PRM
set Analysis                    = wallette
set Additional shared libraries = $library
set Output directory            = results-$1
subsection Wallette
  set Courses                     = 2
  set Length in bricks            = 1
  set Elements along the length   = 2
  set Elements along the width    = 1
  set Elements along the height   = 1
  set Platen direction            = 0, 0, 1
  set Target strain               = 0.0005
  set Number of steps             = 20
  set Write plot                  = false
  set Write VTU                   = false
end
subsection Bond
  set Pattern = stack
end
subsection Interface law
  set Law = bilinear
  subsection Bilinear
    set Tensile strength = 0.2e6
  end
end
subsection Postprocess
  subsection Wallette
    set List of postprocessors = $2
    subsection Peak csv
      set File name = ${3:-peak.csv}
    end
  end
end
PRM
}

write_prm listed "curve tables, peak csv"
expect_documented "$masonry" listed.prm "peak csv" peak.csv
"$masonry" listed.prm >listed.log

write_prm renamed "peak csv" my_peak.csv
"$masonry" renamed.prm >renamed.log

/usr/bin/python3 - <<'PY'
import csv, json, sys
ok = True
def check(cond, what):
    global ok
    print(("OK " if cond else "FAILED ") + what)
    ok = ok and cond
def close(a, b, tol=1e-9):
    return abs(a - b) <= tol * max(1.0, abs(a), abs(b))
rows = list(csv.DictReader(open("results-listed/curve.csv")))
peak = {r["quantity"]: float(r["value"]) for r in csv.DictReader(open("results-listed/peak.csv"))}
top = max(range(len(rows)), key=lambda i: float(rows[i]["stress_Pa"]))
check(int(peak["step"]) == int(rows[top]["step"]) and
      close(peak["strain"], float(rows[top]["strain"])) and
      close(peak["stress_Pa"], float(rows[top]["stress_Pa"])) and
      close(peak["force_N"], float(rows[top]["force_N"])),
      "peak.csv: the step, strain, stress and force of the largest stress of curve.csv")
check(0.9 * 0.2e6 <= peak["stress_Pa"] <= 0.2e6 * (1 + 1e-9) and
      close(peak["height_m"], 0.15),
      "the peak lies between 0.9 f_t and the joint's tensile strength f_t = 0.2 MPa; height 0.15 m")
check(close(peak["max_joint_damage"], float(rows[-1]["max_damage"])) and
      peak["max_joint_damage"] > 0.1,
      "the largest joint damage of the model view = max_damage of the last curve row")
s = json.load(open("results-listed/summary.json"))
check("peak.csv" in s["files"] and s["status"] == "completed",
      "peak.csv is in summary.json's files")
r = json.load(open("results-renamed/summary.json"))
check("my_peak.csv" in r["files"] and "peak.csv" not in r["files"] and
      not any(f.endswith(".vtu") or f.endswith(".png") for f in r["files"]),
      "File name of the plugin's subsection is used; unlisted outputs do not run")
sys.exit(0 if ok else 1)
PY
