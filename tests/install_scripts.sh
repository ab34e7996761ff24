#!/usr/bin/env bash
# An installed masonry writes its picture: `cmake --install` into a prefix,
# move the prefix elsewhere (nothing may point back into the build or source
# tree), run the arch example with the installed executable and check that
# vault.png is a PNG listed in summary.json; without the installed
# vault_picture.py the run says so and writes no picture.
# Usage: install_scripts.sh MASONRY_BUILD_DIR WORK_DIR EXAMPLE_PRM
set -euo pipefail
build=$1
work=$2
example=$3

rm -rf "$work"
mkdir -p "$work"
cd "$work"
cmake --install "$build" --prefix "$work/prefix" >install.log 2>&1 || {
  cat install.log
  exit 1
}
mv prefix moved
test -f moved/share/masonry/scripts/vault_picture.py
echo "installed: bin/masonry, share/masonry/scripts/vault_picture.py"

run() { # name
  cp "$example" "$1.prm"
  echo "set Output directory = $work/results-$1" >>"$1.prm"
  (cd moved/bin && ./masonry "$work/$1.prm" >"$work/$1.log" 2>&1)
}

run installed
/usr/bin/python3 - "$work/results-installed" <<'PY'
import json, sys
d = sys.argv[1]
s = json.load(open(f"{d}/summary.json"))
png = open(f"{d}/vault.png", "rb").read(8) == b"\x89PNG\r\n\x1a\n"
ok = png and "vault.png" in s["files"]
print(f"installed masonry: vault.png {'written' if ok else 'MISSING'}")
sys.exit(0 if ok else 1)
PY

rm moved/share/masonry/scripts/vault_picture.py
run without
if test -e results-without/vault.png || ! grep -q "Note: vault.png not written (vault_picture.py not found)" without.log; then
  echo "without the installed script: unexpected result"
  cat without.log
  exit 1
fi
echo "without the installed script: no vault.png, a note says why"
