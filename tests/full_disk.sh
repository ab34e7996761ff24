#!/usr/bin/env bash
# A run whose output directory fills up: the run ends with a non-zero exit
# and a one-line error naming the file and the system's reason, and every
# file it leaves is whole (XML files parse, JSON parses, text files end with
# a complete line, no temporary file is left). The file system is a tmpfs of
# a fraction of the run's full output (mounted in a private mount namespace,
# so nothing is left mounted); where mounting is not allowed, a file-size
# limit (ulimit -f, with SIGXFSZ ignored) stands in for it, and the reason is
# then "File too large".
# Usage: full_disk.sh MASONRY WORK_DIR EXAMPLE_PRM [APPENDED_PRM]
# (APPENDED_PRM: lines appended to the example, e.g. a shorter run)
set -euo pipefail
masonry=$1
work=$2
example=$3
appended=${4:-}
fractions=(0.02 0.1 0.3 0.5 0.7 0.9)
rm -rf "$work"
mkdir -p "$work"
cd "$work"
cp "$example" example.prm
if [[ -n "$appended" ]]; then
  cat "$appended" >>example.prm
fi
example=$work/example.prm

prm() { # output directory
  cp "$example" run.prm
  printf 'set Output directory = %s\n' "$1" >>run.prm
}

# the whole output, on an ordinary file system
prm full
"$masonry" run.prm >full.log 2>&1 || {
  echo "full_disk: the run without a size limit failed:" >&2
  tail -5 full.log >&2
  exit 1
}
total=$(du -sk --apparent-size full | cut -f1)
largest=$(find full -type f -printf '%s\n' | sort -n | tail -1)

mkdir -p mnt
if unshare -m true 2>/dev/null &&
  unshare -m mount -t tmpfs -o size=4k tmpfs mnt 2>/dev/null; then
  mode=tmpfs
else
  mode=ulimit
fi
echo "full output ${total} kB, largest file ${largest} bytes; limits by $mode"

check_files() { # directory
  /usr/bin/python3 - "$1" <<'PY'
import json, os, sys
import xml.etree.ElementTree as ET
bad = []
for name in sorted(os.listdir(sys.argv[1])):
    path = os.path.join(sys.argv[1], name)
    if name.startswith("."):
        bad.append(f"{name}: a temporary file left behind")
        continue
    data = open(path, "rb").read()
    try:
        if name.endswith((".vtu", ".pvd", ".pvtu", ".xdmf")):
            ET.fromstring(data)
        elif name.endswith(".json"):
            json.loads(data)
        elif name.endswith((".csv", ".txt", ".prm")):
            if data and not data.endswith(b"\n"):
                raise ValueError("ends inside a line")
        elif name.endswith(".png"):
            if not data.endswith(b"IEND\xaeB`\x82"):
                raise ValueError("no PNG end chunk")
        if name == "summary.json" and json.loads(data).get("complete") is not False and \
                json.loads(data).get("status") not in ("completed", "optimal"):
            raise ValueError("an unsuccessful run not marked incomplete")
    except Exception as exc:
        bad.append(f"{name}: {exc}")
for b in bad:
    print("  not whole:", b)
sys.exit(1 if bad else 0)
PY
}

failures=0
for f in "${fractions[@]}"; do
  kb=$(/usr/bin/python3 -c "print(max(4, int($total * $f)))")
  rm -rf out
  mkdir -p out
  status=0
  if [[ $mode == tmpfs ]]; then
    unshare -m bash -c "mount -t tmpfs -o size=${kb}k tmpfs '$work/mnt' &&
      prm_dir='$work/mnt/out' && cd '$work' &&
      cp '$example' run.prm && echo \"set Output directory = \$prm_dir\" >>run.prm &&
      { '$masonry' run.prm >run.log 2>&1; echo \$? >status; } ;
      cp -a '$work/mnt/out/.' '$work/out/' 2>/dev/null || true"
    reason="No space left on device"
  else
    limit=$(/usr/bin/python3 -c "print(max(1, int($largest * $f / 1024)))")
    prm out
    (trap '' XFSZ; ulimit -f "$limit"; "$masonry" run.prm >run.log 2>&1; echo $? >status) || true
    reason="File too large"
  fi
  status=$(cat status)
  line=$(grep -m1 "masonry: error:" run.log || true)
  printf '%-5s of the output (%5s kB): exit %s, %s\n' "$f" "$kb" "$status" "${line:-no error}"
  if grep -q "needs python3-" run.log; then
    echo "  a message blames a missing package for a full disk:" >&2
    grep "needs python3-" run.log >&2
    failures=$((failures + 1))
  fi
  if [[ $status != 0 ]]; then
    if ! [[ $line =~ cannot\ write\ \'[^\']+\':\ $reason ]]; then
      echo "  the error does not name a file and '$reason'" >&2
      failures=$((failures + 1))
    fi
  elif ! cmp -s <(cd full && ls) <(cd out && ls); then
    echo "  exit 0 but the files differ from the full run's" >&2
    failures=$((failures + 1))
  fi
  check_files out || failures=$((failures + 1))
done
if ((failures)); then
  echo "full_disk: $failures failure(s)" >&2
  exit 1
fi
echo "full_disk: every output whole or absent"
