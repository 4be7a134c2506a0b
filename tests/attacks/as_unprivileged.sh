#!/usr/bin/env bash
# Runs a test program as an unprivileged user (uid 65534, no groups) when started as root, so
# that the exam's attacks are tried both ways (issue 28); as any other user, as that user.
# Usage: as_unprivileged.sh PROGRAM [ARGS...]
set -euo pipefail
if [ "$(id -u)" -ne 0 ]; then exec "$@"; fi
home="$(mktemp -d "${TMPDIR:-/tmp}/aula-unprivileged-XXXXXX")"
chmod 777 "$home"
trap 'rm -rf "$home"' EXIT
HOME="$home" XDG_CACHE_HOME="$home/cache" TMPDIR="$home" \
  setpriv --reuid=65534 --regid=65534 --clear-groups "$@"
