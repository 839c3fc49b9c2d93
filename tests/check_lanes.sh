#!/bin/sh
# Copyright (C) 2026 the vsph developers.
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE).
# scripts/check-lanes with a stand-in runner that prints its lane and
# threads (and fails in lane 2 when FAIL2 is set), in a folder whose path
# holds a space and a newline: run by tests/check_library.c
# (test_check_lanes_script), which reads the words it prints.
set -eu
d=$(mktemp -d /tmp/vsph-lanes-XXXXXX)
trap 'rm -rf -- "$d"' EXIT
w="$d/a b
c"
mkdir -p "$w"
lanes="$(dirname "$0")/../scripts/check-lanes"
printf '#!/bin/sh\necho "lane $VSPH_CHECK_LANE threads $OMP_NUM_THREADS"\n[ "$VSPH_CHECK_LANE" = 2 ] && [ -n "${FAIL2:-}" ] && exit 1\nexit 0\n' > "$w/run"
chmod +x "$w/run"
# both lanes run, each with its lane and one thread; both logs shown
out=$("$lanes" "$w/run" "$w")
case $out in *"lane 1 threads 1"*"lane 2 threads 1"*) echo both ;; esac
# a lane that fails fails the whole
s=0; FAIL2=1 "$lanes" "$w/run" "$w" > /dev/null || s=$?
[ "$s" -eq 1 ] && echo fails
# a folder as the runner: refused, exit 2
s=0; "$lanes" "$w" "$w" > /dev/null 2>&1 || s=$?
[ "$s" -eq 2 ] && echo no-folder
# a log it did not write: refused, exit 2, left as it was
printf 'mine\n' > "$w/check-lane-2.log"
s=0; "$lanes" "$w/run" "$w" > /dev/null 2>&1 || s=$?
[ "$s" -eq 2 ] && [ "$(cat "$w/check-lane-2.log")" = mine ] && echo kept
