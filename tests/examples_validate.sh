#!/usr/bin/env bash
# Every shipped example must pass `masonry --validate` (parameters parse,
# geometry and meshes build): a renamed or removed entry breaks no example
# silently. Usage: examples_validate.sh MASONRY EXAMPLES_DIR
set -u
masonry=$1
failed=0
n=0
for prm in "$2"/*.prm; do
  n=$((n + 1))
  if ! out=$("$masonry" --validate "$prm" 2>&1); then
    echo "FAILED: $(basename "$prm"): $out"
    failed=1
  fi
done
# --validate outside mpirun starts no MPI: it answers even where MPI_Init
# would abort (an Open MPI transport that does not exist)
prm=$(ls "$2"/*.prm | head -1)
if ! out=$(OMPI_MCA_pml=no-such-transport "$masonry" --validate "$prm" 2>&1); then
  echo "FAILED: --validate with MPI unusable: $out"
  failed=1
fi
if [[ $n == 0 ]]; then
  echo "FAILED: no examples in $2"
  exit 1
fi
[[ $failed == 0 ]] && echo "OK: all $n examples validate"
exit $failed
