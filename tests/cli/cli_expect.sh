#!/usr/bin/env bash
# cli_expect.sh STATUS REGEX -- COMMAND...: runs COMMAND, requires exit status STATUS and that
# stdout+stderr match REGEX (extended grep).
set -u
want=$1; regex=$2; shift 3
out=$("$@" 2>&1); got=$?
if [[ $got != "$want" ]]; then echo "exit status $got, expected $want; output:"; echo "$out"; exit 1; fi
if ! grep -Eq -- "$regex" <<<"$out"; then echo "output does not match /$regex/:"; echo "$out"; exit 1; fi
echo "ok: status $got, output matches /$regex/"
