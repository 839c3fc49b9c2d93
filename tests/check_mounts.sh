#!/bin/sh
# Copyright (C) 2026 the vsph developers.
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE).
# scripts/mounts.sh against hand-written mount tables (as /proc/mounts
# writes them: a space as \040, a newline as \012, a tab as \011, a
# backslash as \134), for a folder whose path holds a space and a
# newline: run by tests/check_library.c (test_removal_waits_for_mounts), which reads the
# words it prints. Needs no root: no real mount is made.
set -eu
# shellcheck source=scripts/mounts.sh
. "$(dirname "$0")/../scripts/mounts.sh"
d=$(mktemp -d /tmp/vsph-mnt-XXXXXX)
trap 'rm -rf -- "$d"' EXIT
r="$d/a b
c"
mkdir -p "$r/dev"
: > "$r/dev/keep"
# the host's /dev bound below the folder
printf 'proc /proc proc rw 0 0\n/dev %s/dev none rw,bind 0 0\n' \
  "$(vsph_mangle "$r")" > "$d/bound"
vsph_mounted_below "$r" "$d/bound" && echo below
# "a b" is the start of "a b\nc" but not a folder of it
vsph_mounted_below "$d/a b" "$d/bound" || echo prefix-not-below
# a sibling whose name extends the folder's is not below it
printf '/dev %s2/dev none rw 0 0\n' "$(vsph_mangle "$r")" > "$d/sibling"
vsph_mounted_below "$r" "$d/sibling" || echo sibling-not-below
# the folder itself mounted
printf 'tmpfs %s tmpfs rw 0 0\n' "$(vsph_mangle "$r")" > "$d/itself"
vsph_mounted_below "$r" "$d/itself" && echo itself
# nothing removed while the bind is there
vsph_remove_unmounted "$r" "$d/bound" || echo kept
[ -f "$r/dev/keep" ] && echo intact
# removed once the table shows nothing below it
printf 'proc /proc proc rw 0 0\n' > "$d/none"
vsph_remove_unmounted "$r" "$d/none" && [ ! -e "$r" ] && echo removed
# a tab and a backslash escaped as /proc/mounts writes them
t=$(printf '%s/t\tx\\y' "$d")
[ "$(vsph_mangle "$t")" = "$d/t\\011x\\134y" ] && echo escaped
