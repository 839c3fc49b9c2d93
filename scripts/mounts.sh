# shellcheck shell=sh
# Copyright (C) 2026 the vsph developers.
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE).
# Shell functions (POSIX sh, sourced) that scripts/fresh-check uses to
# remove a folder with mounts inside it safely, for any path (spaces,
# tabs, newlines, backslashes). tests/check_library.c (test_mounts) holds
# them to hand-written /proc/mounts lines.

# $1 as /proc/mounts writes a path (space, tab, newline and backslash as
# octal escapes)
vsph_mangle() {
  printf '%s' "$1" | awk '{ gsub(/\\/, "\\134"); gsub(/ /, "\\040");
    gsub(/\t/, "\\011"); printf "%s%s", (NR > 1 ? "\\012" : ""), $0 }'
}

# whether anything is mounted at or below folder $1, by the mount table
# $2 (default /proc/mounts) read exactly, its escapes matched (the path
# through the environment, which awk takes as it is)
vsph_mounted_below() {
  R=$(vsph_mangle "$1") awk '$2 == ENVIRON["R"] ||
    index($2, ENVIRON["R"] "/") == 1 { f = 1 } END { exit !f }' \
    "${2:-/proc/mounts}"
}

# remove folder $1 unless anything is still mounted at or below it (by
# the mount table $2, default /proc/mounts): never delete through a mount
# that is still there (it could be the host's /dev). Returns 1, removing
# nothing, where something is.
vsph_remove_unmounted() {
  if vsph_mounted_below "$1" "${2:-/proc/mounts}"; then
    return 1
  fi
  rm -rf --one-file-system -- "$1"
}
