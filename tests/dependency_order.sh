#!/usr/bin/env bash
# libmasonry lists its dependencies in the order of
# cmake/dependency-order.sh (CMakeLists.txt, MASONRY_ORDER_DEPENDENCIES): it
# shortens the dynamic loader's symbol lookups and must not change what a
# symbol resolves to. The reference is the loader itself loading libdeal.ii
# on its own (its data relocations, as `ldd -d` does): every C symbol that
# the same library binds in both must bind to the same library in
# `masonry --validate`, unless it binds in the launcher's own scope. (C++ symbols are left out: most of them are
# template instances and inline functions that many libraries define alike.)
# The default order fails this: it binds libcrypto's own SCT_free to
# libsuperlu_dist's function of the same name.
# Usage: dependency_order.sh MASONRY LIBMASONRY PRM WORK_DIR
set -u
masonry=$(realpath "$1")
libmasonry=$(realpath "$2")
prm=$(realpath "$3")
work=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1

dealii=$(ldd "$libmasonry" | awk '$1 ~ /^libdeal\.ii/ {print $3; exit}')
loader=$(ldd "$libmasonry" | awk '$2 != "=>" && $1 ~ /^\// {print $1; exit}')
if [[ -z $dealii || -z $loader ]]; then
  echo "FAILED: libdeal.ii or the dynamic loader not found by ldd"
  exit 1
fi
first=$(readelf -d "$libmasonry" | awk '/NEEDED/ {gsub(/[][]/, "", $5); print $5; exit}')
echo "libmasonry's first dependency: $first"

# "file symbol library" for every binding, C symbols only; the loader
# names a library by the path it opened, so paths go through realpath
bindings() {
  awk '/binding file/ {
         file = ""; to = ""; sym = ""
         for (i = 1; i < NF; ++i) {
           if ($i == "file" && file == "") file = $(i + 1)
           if ($i == "to") to = $(i + 1)
           if ($i == "symbol") sym = $(i + 1)
         }
         gsub(/[`'"'"']/, "", sym)
         if (sym !~ /^_Z/) print file, sym, to
       }'
}
LD_TRACE_LOADED_OBJECTS=1 LD_WARN=yes LD_DEBUG=bindings "$loader" "$dealii" \
  2>&1 >/dev/null | bindings | sort -u >alone.txt
LD_DEBUG=bindings "$masonry" --validate "$prm" 2>&1 >/dev/null | bindings |
  sort -u >masonry.txt

# canonical paths (the same library may be named by two paths)
awk '{print $1; print $3}' alone.txt masonry.txt | sort -u >paths.txt
while read -r p; do echo "$p $(realpath -m "$p")"; done <paths.txt >real.txt

# The launcher and its own libraries (libc, libm, libstdc++: the global
# scope) come before libmasonry's list in every lookup, so a binding to one
# of them is not the list's doing: a copy relocation into the executable
# (stdout, environ), or glibc's modf, frexp and ldexp, which libc and libm
# both define.
{
  echo "$masonry"
  ldd "$masonry" | awk '$2 == "=>" && $3 ~ /^\// {print $3}
                        $2 != "=>" && $1 ~ /^\// {print $1}'
} | while read -r p; do realpath -m "$p"; done >global.txt
awk -v real=real.txt -v global=global.txt '
  BEGIN {
    while ((getline line < real) > 0) { split(line, f, " "); r[f[1]] = f[2] }
    while ((getline line < global) > 0) scope[line] = 1
  }
  FNR == 1 { ++file }
  file == 1 { alone[r[$1] " " $2] = r[$3]; next }
  {
    key = r[$1] " " $2
    if ((key in alone) && !(r[$3] in scope)) {
      ++common
      if (alone[key] != r[$3]) {
        ++differ
        if (differ <= 10) print "differs: " $1 " " $2 ": alone " alone[key] ", masonry " r[$3]
      }
    }
  }
  END {
    printf "C-symbol bindings compared: %d, different: %d\n", common, differ
    # a comparison of nothing proves nothing: libdeal.ii alone binds
    # tens of thousands of C symbols that masonry binds too
    if (common < 10000) { print "FAILED: too few bindings to compare"; exit 1 }
    if (differ > 0) { print "FAILED: the dependency order changed what symbols resolve to"; exit 1 }
    print "OK: every compared C symbol resolves to the same library"
  }' alone.txt masonry.txt
