#!/usr/bin/env bash
# The launcher names OpenBLAS's kernels by the processor's instruction
# sets (source/main.cc): SkylakeX with AVX-512 F, CD, BW, DQ and VL,
# Haswell with AVX2 and FMA, otherwise OpenBLAS's own choice; a user's
# OPENBLAS_CORETYPE is kept. The expected kernels are read here from the
# flags in /proc/cpuinfo, independently of the launcher, and compared with
# what OpenBLAS reports it loaded (OPENBLAS_VERBOSE=2 prints "Core: NAME").
# Skipped (exit 77) where the BLAS is not OpenBLAS with run-time kernel
# selection. Usage: blas_kernels.sh MASONRY PRM
set -u
masonry=$1
prm=$2
core() {
  "$@" --validate "$prm" 2>&1 | sed -n 's/^Core: //p' | head -1
}
# the launcher's own choice: without a user's OPENBLAS_CORETYPE (a
# machine may set one for every process)
default=$(OPENBLAS_VERBOSE=2 core env -u OPENBLAS_CORETYPE "$masonry")
if [[ -z $default ]]; then
  echo "SKIPPED: the BLAS does not report its kernels (not OpenBLAS with DYNAMIC_ARCH)"
  exit 77
fi
flags=" $(grep -m1 '^flags' /proc/cpuinfo | cut -d: -f2) "
has() { [[ $flags == *" $1 "* ]]; }
expected=
if has avx512f && has avx512cd && has avx512bw && has avx512dq && has avx512vl; then
  expected=SkylakeX
elif has avx2 && has fma; then
  expected=Haswell
fi
failed=0
if [[ -n $expected && $default != "$expected" ]]; then
  echo "FAILED: OpenBLAS loaded the $default kernels, the processor's flags ask for $expected"
  failed=1
fi
kept=$(OPENBLAS_VERBOSE=2 OPENBLAS_CORETYPE=Prescott core "$masonry")
if [[ $kept != Prescott ]]; then
  echo "FAILED: OPENBLAS_CORETYPE=Prescott gave the $kept kernels (the user's choice must win)"
  failed=1
fi
[[ $failed == 0 ]] && echo "OK: kernels ${default} (expected ${expected:-the library default}); a user's choice kept"
exit $failed
