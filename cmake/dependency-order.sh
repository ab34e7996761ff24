#!/bin/sh
# dependency-order.sh LIBRARY
#
# Prints the shared libraries that LIBRARY loads (itself included), one path
# per line, in an order that makes the dynamic loader's symbol lookups
# short without changing what any symbol resolves to.
#
# Used by CMakeLists.txt to order libmasonry's DT_NEEDED entries. The
# loader resolves every symbolic relocation by walking the loaded
# libraries in breadth-first order until one defines the symbol. libdeal.ii
# loads about 200 libraries with about 330 000 relocations; in their
# breadth-first order a lookup walks past about 38 libraries on average.
# Libraries that many relocations bind to should come first.
#
# 1. The load (= search) order and the bindings come from the loader
#    itself: with LD_TRACE_LOADED_OBJECTS and LD_WARN set it loads LIBRARY
#    and performs its data relocations without running anything (what
#    `ldd -d` does); LD_DEBUG=bindings prints where each one binds.
# 2. A symbol that several libraries define, at least one of them with a
#    strong (not weak) definition, binds to the first of them in the search
#    order (e.g. BLAS in libblas and libopenblas, SCOTCH in libscotch and
#    libptscotch). Each such first definer must stay before the others, so
#    these pairs (from `nm -D --defined-only`) are kept as constraints.
#    Weak definitions (inline functions, template instances) that only
#    other weak definitions repeat are interchangeable and not constrained.
# 3. The order: the ratio rule for a sequence with precedence constraints
#    (each library placed costs every later lookup one step, each binding
#    saves one): repeatedly the library whose group (itself and the
#    libraries that must precede it) has the most bindings per library,
#    with its group (ties: the load order).
#
# Prints nothing (exit 0) if the loader or nm is missing or says nothing,
# so the caller keeps the default order.
set -u
library=${1:?usage: dependency-order.sh LIBRARY}
command -v nm >/dev/null 2>&1 || exit 0

# the dynamic loader: the ldd line without "=>", e.g.
# "	/lib64/ld-linux-x86-64.so.2 (0x...)"
loader=$(ldd "$library" 2>/dev/null | awk '$2 != "=>" && $1 ~ /^\// {print $1; exit}')
[ -n "$loader" ] && [ -x "$loader" ] || exit 0

tmp=$(mktemp -d) || exit 0
trap 'rm -rf "$tmp"' EXIT

# load order: LIBRARY, then the "name => path (address)" lines
{
  echo "$library"
  LD_TRACE_LOADED_OBJECTS=1 "$loader" "$library" 2>/dev/null |
    awk '$2 == "=>" && $3 ~ /^\// {print $3}'
} | awk -v loader="${loader##*/}" \
  '{ n = split($1, part, "/"); if (part[n] != loader && !seen[$1]++) print }' \
  >"$tmp/load"
[ -s "$tmp/load" ] || exit 0

# bindings per library (the loader names a library by the path it opened)
LD_TRACE_LOADED_OBJECTS=1 LD_WARN=yes LD_DEBUG=bindings "$loader" "$library" 2>&1 >/dev/null |
  awk '/binding file/ { for (i = 1; i < NF; ++i) if ($i == "to") { n[$(i + 1)]++; break } }
       END { for (f in n) print f, n[f] }' >"$tmp/bindings"

# defined dynamic symbols: "library-index strong(0/1) name"
index=0
while read -r path; do
  index=$((index + 1))
  nm -D --defined-only "$path" 2>/dev/null |
    awk -v i="$index" 'NF >= 3 && $2 != "A" {
      print i, ($2 ~ /^[TDBRGSi]$/ ? 1 : 0), $3 }'
done <"$tmp/load" >"$tmp/symbols"

awk -v bindings="$tmp/bindings" -v symbols="$tmp/symbols" '
  BEGIN {
    while ((getline line < bindings) > 0) {
      split(line, f, " "); count[f[1]] = f[2]
    }
  }
  { path[NR] = $1; libs = NR; c[NR] = ($1 in count) ? count[$1] : 0 }
  END {
    # constraints: the first definer of a symbol before every later one,
    # if any definition of it is strong
    while ((getline line < symbols) > 0) {
      split(line, f, " "); i = f[1] + 0; s = f[3]
      if (s in first) {
        if (f[2] == 1 || firststrong[s]) strongsym[s] = 1
        if (i != first[s]) later[s] = later[s] " " i
      } else {
        first[s] = i; firststrong[s] = f[2]
      }
    }
    for (s in strongsym) {
      m = split(later[s], l, " ")
      for (k = 1; k <= m; ++k) {
        key = first[s] SUBSEP l[k]
        edge[key] = 1
      }
    }
    for (key in edge) { split(key, e, SUBSEP); preds[e[2]] = preds[e[2]] " " e[1] }
    # Order by the ratio rule for precedence constraints: each step takes
    # the library j whose group (j and its predecessors not yet placed)
    # has the most bindings per library, and places that group, its
    # libraries with met constraints first and most bindings first.
    placedcount = 0
    while (placedcount < libs) {
      best = 0
      for (j = 1; j <= libs; ++j) {
        if (placed[j]) continue
        ++stamp; size = 0; sum = 0; group(j)
        if (best == 0 || sum * bestsize > bestsum * size) {
          best = j; bestsum = sum; bestsize = size
        }
      }
      ++stamp; size = 0; sum = 0; group(best)
      for (left = size; left > 0; --left) {
        pick = 0
        for (k = 1; k <= libs; ++k)
          if (mark[k] == stamp && !placed[k] && ready(k) && (pick == 0 || c[k] > c[pick]))
            pick = k
        if (pick == 0) exit 1  # a cycle: cannot happen for a first-definer order
        placed[pick] = 1; ++placedcount; print path[pick]
      }
    }
  }
  # marks j and its unplaced predecessors with the current stamp; adds
  # their number and their bindings to size and sum
  function group(j,    m, l, k) {
    if (placed[j] || mark[j] == stamp) return
    mark[j] = stamp; ++size; sum += c[j]
    m = split(preds[j], l, " ")
    for (k = 1; k <= m; ++k) group(l[k])
  }
  function ready(j,    m, l, k) {
    m = split(preds[j], l, " ")
    for (k = 1; k <= m; ++k) if (!placed[l[k]]) return 0
    return 1
  }' "$tmp/load" >"$tmp/order" || exit 0
cat "$tmp/order"
