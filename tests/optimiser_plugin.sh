#!/usr/bin/env bash
# Configure and build contrib/examples/optimiser (pagmo's sade as a
# mesh-adaptation optimiser) out of tree against this build tree's
# masonryConfig.cmake, load it with `Additional shared libraries` and adapt
# the blocks of the arch-minimum-thickness-adapted example with it. Theory:
# the block layouts of a semicircular arch (R = 5 m, radial joints, no
# tension, no sliding) stand at thicknesses below the continuous arch's
# five-hinge minimum t/R = 0.107478 (with true block centroids; see
# tests/vault_tests.h), and the best layout approaches it from below; the
# uniform layout of 4 blocks per half is further from it.
# Usage: optimiser_plugin.sh PLUGIN_SOURCE MASONRY_BUILD_DIR MASONRY WORK_DIR EXAMPLE
set -euo pipefail
source_dir=$1
masonry_build=$2
masonry=$3
work=$4
example=$5

source "$(dirname "${BASH_SOURCE[0]}")/plugin_common.sh"
build_plugin "$source_dir" "$masonry_build" "$work" sade_optimiser

{
  echo "set Additional shared libraries = $library"
  echo "set Output directory = results"
  sed 's/^\( *set Optimiser *\)= .*/\1= self-adaptive differential evolution/' "$example"
} >sade.prm
"$masonry" sade.prm >run.log 2>&1 || {
  cat run.log
  exit 1
}
/usr/bin/python3 - <<'PY'
import json, sys
s = json.load(open("results/summary.json"))
a = s["adaptation"]
R, theory = 5.0, 0.107478
t_best, t_uniform = a["best_fitness"] * 1.0 / R, a["uniform_fitness"] * 1.0 / R
checks = [
    (a["optimiser"] == "self-adaptive differential evolution",
     f"optimiser: {a['optimiser']}"),
    (a["failed_evaluations"] == 0, f"failed evaluations: {a['failed_evaluations']}"),
    (t_best <= theory * (1 + 1e-5), f"adapted t/R {t_best:.6f} not above {theory} (+1e-5)"),
    (t_best >= theory * (1 - 5e-3), f"adapted t/R {t_best:.6f} within 0.5 % of {theory}"),
    (t_uniform < t_best, f"uniform t/R {t_uniform:.6f} below the adapted one"),
]
for ok, text in checks:
    print(("ok " if ok else "WRONG ") + text)
sys.exit(0 if all(ok for ok, _ in checks) else 1)
PY
