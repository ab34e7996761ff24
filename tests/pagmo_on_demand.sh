#!/usr/bin/env bash
# pagmo is loaded only by a run that adapts its blocks (pagmo_runner.h):
# `--validate', `--print-parameters' and a run without adaptation never
# load libpagmo, while a run with `Optimiser = genetic' does (the positive
# control: it shows that the dynamic loader's log names libpagmo when it is
# loaded). The selection still offers the pagmo algorithms without it.
# Usage: pagmo_on_demand.sh MASONRY EXAMPLES_DIR WORK_DIR
set -u
masonry=$1
examples=$2
work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
failed=0
loads_pagmo() {
  LD_DEBUG=files "$@" 2>&1 >/dev/null | grep -q 'file=libpagmo\.so'
}
check() { # expected (yes|no), description, command...
  local expected=$1 what=$2
  shift 2
  if loads_pagmo "$@"; then got=yes; else got=no; fi
  if [[ $got == "$expected" ]]; then
    echo "OK $what: libpagmo loaded: $got"
  else
    echo "FAILED $what: libpagmo loaded: $got, expected $expected"
    failed=1
  fi
}
check no "--validate of a settlement example" \
  "$masonry" --validate "$examples/arch-vertical-settlement.prm"
check no "--validate of an adapted example" \
  "$masonry" --validate "$examples/arch-minimum-thickness-adapted.prm"
check no "--print-parameters" "$masonry" --print-parameters
check no "a settlement run without adaptation" \
  "$masonry" "$examples/arch-vertical-settlement.prm"
check yes "a minimum-thickness run with the genetic algorithm" \
  "$masonry" "$examples/arch-minimum-thickness-adapted.prm"
# every built-in algorithm's name and entries are known without pagmo
for name in genetic "differential evolution" cmaes "particle swarm"; do
  sed "s/^\( *set Optimiser *=\).*/\1 $name/" \
    "$examples/arch-minimum-thickness-adapted.prm" >"optimiser.prm"
  if "$masonry" --validate optimiser.prm >/dev/null 2>&1; then
    check no "--validate with Optimiser = $name" \
      "$masonry" --validate optimiser.prm
  else
    echo "FAILED --validate rejects Optimiser = $name"
    failed=1
  fi
done
exit $failed
