#!/usr/bin/env bash
# A picture that fails is absent, never half written, and the run says why
# in one line. The arch example runs twice with a copy of the installed
# scripts (MASONRY_SCRIPT_DIR): first vault_picture.py writes half a PNG and
# then imports a module that is not installed: a note names the module and
# its Debian package, and the run completes without vault.png; then
# crack_map.py writes half a PNG and finds the disk full (an OSError
# ENOSPC, as a full disk raises it): the run ends with the error
# "cannot write '.../crack_map.png': No space left on device" and summary.json
# says it is not complete. Neither picture nor a temporary file is left.
# Usage: picture_failures.sh MASONRY_BUILD_DIR MASONRY WORK_DIR EXAMPLE_PRM
set -euo pipefail
build=$1
masonry=$2
work=$3
example=$4

rm -rf "$work"
mkdir -p "$work"
failed=0
run() { # name: runs the example with the scripts of $work/scripts-NAME
  cp "$example" "$work/$1.prm"
  echo "set Output directory = $work/$1" >>"$work/$1.prm"
  MASONRY_SCRIPT_DIR="$work/scripts-$1" "$masonry" "$work/$1.prm" >"$work/$1.log" 2>&1 ||
    echo "exit $?" >>"$work/$1.log"
}
expect() { # log pattern description
  if grep -qF -- "$2" "$work/$1.log"; then
    echo "OK $3"
  else
    echo "FAILED $3: no line '$2' in $1.log"
    failed=1
  fi
}
no_pictures() { # name pattern: no temporary file and no file matching
  local left
  left=$(cd "$work/$1" && ls -A | grep -E "^\\.|$2" || true)
  if [[ -n "$left" ]]; then
    echo "FAILED $1: pictures or temporary files left: $left"
    failed=1
  else
    echo "OK $1: no picture and no temporary file left"
  fi
}

cp -r "$build/share/masonry/scripts" "$work/scripts-module"
cat >"$work/scripts-module/vault_picture.py" <<'PY'
import sys
open(sys.argv[2], "wb").write(b"\x89PNG half")
import masonry_test_no_such_module  # noqa: F401
PY
cat >"$work/scripts-module/crack_map.py" <<'PY'
PY
run module
expect module "Note: vault.png not written (vault_picture.py failed: missing Python module 'masonry_test_no_such_module' (install the Debian package python3-masonry_test_no_such_module))" \
  "the missing module and its package named"
no_pictures module 'vault\.png'
/usr/bin/python3 - "$work/module" <<'PY' || failed=1
import json, sys
s = json.load(open(sys.argv[1] + "/summary.json"))
ok = (s["status"] == "optimal" and s["complete"] and "report.html" in s["files"]
      and "crack_map.csv" in s["files"] and "vault.png" not in s["files"])
print(("OK" if ok else "FAILED") + " a missing module: the run completed with report.html and crack_map.csv, without vault.png")
sys.exit(0 if ok else 1)
PY

cp -r "$build/share/masonry/scripts" "$work/scripts-disk"
cat >"$work/scripts-disk/crack_map.py" <<'PY'
import errno, os, sys
open(sys.argv[2], "wb").write(b"\x89PNG half")
raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
PY
run disk
expect disk "masonry: error: cannot write '$work/disk/crack_map.png': No space left on device" \
  "a full disk ends the run, naming the file and the reason"
expect disk "exit 1" "a full disk: exit code 1"
no_pictures disk 'crack_map\.png'
/usr/bin/python3 - "$work/disk" <<'PY' || failed=1
import json, sys
s = json.load(open(sys.argv[1] + "/summary.json"))
ok = s["status"] == "error" and s["complete"] is False
print(("OK" if ok else "FAILED") + " a full disk: summary.json says error, not complete")
sys.exit(0 if ok else 1)
PY
exit $failed
