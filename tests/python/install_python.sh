#!/bin/sh
# `cmake --install BUILD --component python` (issue 48): the module lands in the interpreter's own
# site-packages, so `import splinex` needs no PYTHONPATH. Installed into a DESTDIR here (the test
# does not write into the system), imported from there, and the directory checked to be on the
# interpreter's default sys.path.
set -eu
build=$1
python=$2
dir=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
DESTDIR="$tmp" cmake --install "$build" --component python > "$tmp/install.log"
ls "$tmp$dir"/splinex*.so > /dev/null || { echo "no module under $tmp$dir"; cat "$tmp/install.log"; exit 1; }
env -u PYTHONPATH "$python" -c "import sys; d = sys.argv[1]; assert d in sys.path, (d, sys.path)" "$dir" \
  || { echo "$dir is not on $python's sys.path: set -DSPLINEX_PYTHON_INSTALL_DIR"; exit 1; }
cd "$tmp"
PYTHONPATH="$tmp$dir" "$python" -c "
import splinex
S = {'degrees': [1], 'knots': [[0, 0, 1, 1]], 'points': [[0], ['1/3']]}
print(splinex.evaluate(S, '1/2')[0], splinex.__file__.startswith('$tmp'))"
