#!/usr/bin/env bash
# Shared steps of the out-of-tree plugin tests (sourced, not run).

# build_plugin SOURCE_DIR MASONRY_BUILD_DIR WORK_DIR LIBRARY_NAME
# Configures and builds SOURCE_DIR in WORK_DIR/build against the
# masonryConfig.cmake of MASONRY_BUILD_DIR, leaves the shell in WORK_DIR and
# sets `library' to the built shared library. Prints the CMake log and exits
# non-zero if a step fails.
build_plugin() {
  local source_dir=$1 masonry_build=$2 work=$3 name=$4
  rm -rf "$work"
  mkdir -p "$work"
  cd "$work"
  echo "--- configuring $name against $masonry_build"
  cmake -S "$source_dir" -B build -Dmasonry_DIR="$masonry_build" >cmake.log 2>&1 || {
    cat cmake.log
    exit 1
  }
  echo "--- building"
  cmake --build build >build.log 2>&1 || {
    cat build.log
    exit 1
  }
  library="$work/build/lib$name.so"
  test -f "$library"
}

# expect_documented MASONRY PRM NAME FILE
# --print-parameters of PRM documents the postprocessor NAME, writing FILE,
# under `List of postprocessors'.
expect_documented() {
  local masonry=$1 prm=$2 name=$3 file=$4
  # (grep reads the whole text: grep -q would stop early and, under pipefail,
  # the SIGPIPE of masonry would count as a failure)
  "$masonry" --print-parameters "$prm" | grep "^    # \`$name': $file" >/dev/null || {
    echo "$name is not documented under List of postprocessors"
    exit 1
  }
  echo "$name: documented under List of postprocessors by --print-parameters"
}
