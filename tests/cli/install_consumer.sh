#!/bin/sh
# find_package(splinex) from another project: install the build into a temporary prefix, then
# configure, build and run examples/consumer against it: the composition kernel's consumer
# (its output is the test's match) and the verify API's (splinex::crosscheck, every dependency).
set -eu
build=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" > "$tmp/install.log"
cmake -S "$src/examples/consumer" -B "$tmp/b" -DCMAKE_PREFIX_PATH="$tmp/prefix" -DCMAKE_BUILD_TYPE=Release > "$tmp/configure.log" \
  || { cat "$tmp/configure.log"; exit 1; }
cmake --build "$tmp/b" > "$tmp/build.log" || { cat "$tmp/build.log"; exit 1; }
"$tmp/b/consumer"
"$tmp/b/verify" > "$tmp/verify.log" || { cat "$tmp/verify.log"; exit 1; }
"$tmp/b/vrep_boolean" "$src/tests/data/vmodel_box.json" "$src/tests/data/vrep_box_field.json" > "$tmp/vrep.log" 2>&1 \
  && grep -q "^intersection: 1 cell(s), planar cuts$" "$tmp/vrep.log" || { cat "$tmp/vrep.log"; exit 1; }
