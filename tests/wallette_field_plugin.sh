#!/usr/bin/env bash
# Build contrib/examples/wallette_field (the output `cell strain') out of
# tree against this build tree and load it with `Additional shared
# libraries'. It reads the mesh, the DoF handler, the solution, the cells
# and the point states through the public model view and writes a cell field
# to VTU:
# - an elastic wallette of two stack-bonded bricks with elastic joints and
#   platens free to slide is in uniaxial compression, so every cell's strain
#   is the theory's: eps_zz = -sigma / E and eps_xx = eps_yy = nu sigma / E,
#   sigma the stress of curve.csv, E = 10 GPa and nu = 0.15 the bricks'
#   moduli of the file; on two ranks the file holds the same cells and
#   strains;
# - on a damage-plasticity wallette pulled apart, the cell average of the
#   state variable `damage_tension' chosen by name equals the field of the
#   same name of the built-in solution output, and some cells have cracked;
# - a name the material does not declare stops the run with an error that
#   names it.
# Usage: wallette_field_plugin.sh PLUGIN_SOURCE MASONRY_BUILD_DIR MASONRY WORK_DIR
set -euo pipefail
source_dir=$1
masonry_build=$2
masonry=$3
work=$4

source "$(dirname "${BASH_SOURCE[0]}")/plugin_common.sh"
build_plugin "$source_dir" "$masonry_build" "$work" cell_strain

write_prm() { # name material direction strain [state variable]
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
  set Platen direction            = $3
  set Platen lateral restraint    = free
  set Target strain               = $4
  set Number of steps             = 4
  set Write plot                  = false
end
subsection Bond
  set Pattern = stack
end
subsection Brick material
  set Model = $2
end
subsection Interface law
  set Law = elastic
end
subsection Postprocess
  subsection Wallette
    set List of postprocessors = curve tables, fields, cell strain
    subsection Cell strain
      set State variable = ${5:-}
    end
  end
end
PRM
}

write_prm elastic elastic "0, 0, -1" 0.0005
expect_documented "$masonry" elastic.prm "cell strain" PREFIX_NNNN.pvtu
"$masonry" elastic.prm >elastic.log

# the same on two ranks: each writes its own cells into one file
cp elastic.prm elastic_mpi.prm
sed -i 's|results-elastic|results-elastic_mpi|' elastic_mpi.prm
mpirun --allow-run-as-root --oversubscribe -np 2 "$masonry" elastic_mpi.prm >elastic_mpi.log

write_prm cracked "damage plasticity" "0, 0, 1" 0.002 damage_tension
"$masonry" cracked.prm >cracked.log

write_prm unknown "damage plasticity" "0, 0, 1" 0.002 no_such_variable
if "$masonry" unknown.prm >unknown.log 2>&1; then
  echo "FAILED: a state variable the material does not declare did not stop the run"
  exit 1
fi
grep "Cell strain/State variable = no_such_variable" unknown.log | grep "damage_tension" >/dev/null || {
  echo "FAILED: the error does not name the entry's value and the variables there are:"
  cat unknown.log
  exit 1
}
echo "OK an unknown state variable stops the run with an error naming it and listing the material's"

/usr/bin/python3 - <<'PY'
import csv, glob, json, sys
import meshio
ok = True
def check(cond, what):
    global ok
    print(("OK " if cond else "FAILED ") + what)
    ok = ok and cond
def last(pattern):
    return sorted(glob.glob(pattern))[-1]
def pieces(record):
    # the pieces of a .pvtu record, in rank order
    return sorted(glob.glob(record[:-len(".pvtu")] + ".*.vtu"))
def cells(path, name):
    # deal.II writes a cell field as the value at each of the cell's
    # vertices (its own copies): one value per hexahedron
    values = []
    for piece in pieces(path) if path.endswith(".pvtu") else [path]:
        m = meshio.read(piece)
        values += [float(m.point_data[name][c[0]]) for c in m.cells[0].data]
    return values

rows = list(csv.DictReader(open("results-elastic/curve.csv")))
sigma = float(rows[-1]["stress_Pa"])
E, nu = 10e9, 0.15
f = last("results-elastic/cell_strain_*.pvtu")
zz, xx, yy = cells(f, "strain_zz"), cells(f, "strain_xx"), cells(f, "strain_yy")
check(len(zz) == 4, "%s has the wallette's 4 cells" % f)
check(sigma > 0 and all(abs(e + sigma / E) <= 1e-6 * sigma / E for e in zz),
      "eps_zz = -sigma/E = %.6e in every cell (%s)" % (-sigma / E, ", ".join("%.6e" % e for e in zz)))
check(all(abs(e - nu * sigma / E) <= 1e-6 * sigma / E for e in xx + yy),
      "eps_xx = eps_yy = nu sigma/E = %.6e in every cell" % (nu * sigma / E))
def by_centre(record, name):
    values = {}
    for piece in pieces(record):
        m = meshio.read(piece)
        for c in m.cells[0].data:
            key = tuple(round(x, 9) for x in m.points[c].mean(axis=0))
            values[key] = values.get(key, []) + [float(m.point_data[name][c[0]])]
    return values
one = by_centre(f, "strain_zz")
two = by_centre(last("results-elastic_mpi/cell_strain_*.pvtu"), "strain_zz")
check(len(pieces(last("results-elastic_mpi/cell_strain_*.pvtu"))) == 2 and
      len(two) == 4 and set(one) == set(two) and
      all(len(v) == 1 for v in two.values()) and
      all(abs(one[k][0] - two[k][0]) <= 1e-9 * abs(one[k][0]) for k in one),
      "on two ranks the two pieces hold every cell once, with the serial run's strains")
s = json.load(open("results-elastic/summary.json"))
check(s["status"] == "completed" and f.split("/")[-1] in s["files"] and
      all(p.split("/")[-1] in s["files"] for p in pieces(f)),
      "the plugin's files are in summary.json's files")

f = last("results-cracked/cell_strain_*.pvtu")
mine = cells(f, "damage_tension")
builtin = cells(last("results-cracked/solution_*.vtu"), "damage_tension")
check(len(mine) == len(builtin) and
      all(abs(a - b) <= 1e-6 * max(1.0, abs(b)) for a, b in zip(mine, builtin)),
      "damage_tension by name = the built-in field, cell by cell (%s)" % ", ".join("%.4f" % d for d in mine))
check(max(mine) > 0.1, "some cells have cracked (largest damage_tension %.3f)" % max(mine))
sys.exit(0 if ok else 1)
PY
