#!/usr/bin/env bash
# A picture that fails is absent, never half written, and the run says why
# in one line. The arch example runs with a copy of the installed scripts
# (MASONRY_SCRIPT_DIR) in which vault_picture.py writes half a PNG and then
# imports a module that is not installed, and crack_map.py writes half a
# PNG and then finds the disk full (an OSError ENOSPC, as a full disk
# raises it). Expected: notes naming the missing module and its Debian
# package, and "disk full"; neither picture nor a temporary file left in the
# output directory; the run completed with report.html and its data files.
# Usage: picture_failures.sh MASONRY_BUILD_DIR MASONRY WORK_DIR EXAMPLE_PRM
set -euo pipefail
build=$1
masonry=$2
work=$3
example=$4

rm -rf "$work"
mkdir -p "$work"
cp -r "$build/share/masonry/scripts" "$work/scripts"
cat >"$work/scripts/vault_picture.py" <<'PY'
import sys
open(sys.argv[2], "wb").write(b"\x89PNG half")
import masonry_test_no_such_module  # noqa: F401
PY
cat >"$work/scripts/crack_map.py" <<'PY'
import errno, os, sys
open(sys.argv[2], "wb").write(b"\x89PNG half")
raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
PY
cp "$example" "$work/run.prm"
echo "set Output directory = $work/results" >>"$work/run.prm"
MASONRY_SCRIPT_DIR="$work/scripts" "$masonry" "$work/run.prm" >"$work/log" 2>&1

failed=0
expect() { # pattern description
  if grep -qF -- "$1" "$work/log"; then
    echo "OK $2"
  else
    echo "FAILED $2: no line '$1' in the log"
    failed=1
  fi
}
expect "Note: vault.png not written (vault_picture.py failed: missing Python module 'masonry_test_no_such_module' (install the Debian package python3-masonry_test_no_such_module))" \
  "the missing module and its package named"
expect "Note: crack_map.png not written (crack_map.py failed: disk full (No space left on device))" \
  "a full disk named"
left=$(cd "$work/results" && ls -A | grep -E '^\.|vault\.png|crack_map\.png' || true)
if [[ -n "$left" ]]; then
  echo "FAILED pictures or temporary files left: $left"
  failed=1
else
  echo "OK no picture and no temporary file left"
fi
/usr/bin/python3 - "$work/results" <<'PY' || failed=1
import json, sys
s = json.load(open(sys.argv[1] + "/summary.json"))
ok = (s["status"] == "optimal" and s["complete"] and "report.html" in s["files"]
      and "crack_map.csv" in s["files"] and "vault.png" not in s["files"]
      and "crack_map.png" not in s["files"])
print(("OK" if ok else "FAILED") + " the run completed with report.html and crack_map.csv, without the pictures")
sys.exit(0 if ok else 1)
PY
exit $failed
