#!/usr/bin/env bash
# Solves a directory of Regio scenes on the machines of a host list over ssh,
# without a scheduler: xargs keeps a scene running in every slot, and
# `regio-solve summary` prints the table at the end.
#
#   tools/ssh/solve-over-ssh.sh HOSTS SCENE_DIR OUT_DIR [-- SOLVE OPTIONS...]
#
# HOSTS has a line per slot: a host name as ssh knows it (user@host works),
# or ":" for this machine without ssh; a host of N cores takes N lines. The
# scenes and OUT_DIR must be at the same path on every host (a shared file
# system), regio-solve on every host's PATH (or $REGIO_SOLVE, the same path
# everywhere). Each slot takes the next scene when its last one is done, and
# running the command again resumes: solved scenes are skipped. Ctrl-C stops
# every slot; each stops its scene cleanly. docs/batch.md explains it.
set -euo pipefail

[ $# -ge 3 ] || { sed -n '2,16p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//' >&2; exit 2; }
hosts_file=$1; scene_dir=$2; out_dir=$3; shift 3
[ "${1:-}" = "--" ] && shift
regio_solve=${REGIO_SOLVE:-regio-solve}

mapfile -t hosts < <(grep -v '^[[:space:]]*\(#\|$\)' "$hosts_file")
[ ${#hosts[@]} -gt 0 ] || { echo "solve-over-ssh.sh: no host in $hosts_file" >&2; exit 2; }
mkdir -p "$out_dir"
out_dir=$(realpath "$out_dir")
mapfile -t scenes < <(find "$(realpath "$scene_dir")" -maxdepth 1 -name '*.json' ! -name '*.report.json' |
  LC_ALL=C sort)
[ ${#scenes[@]} -gt 0 ] || { echo "solve-over-ssh.sh: no *.json scene in $scene_dir" >&2; exit 2; }

# A slot is a FIFO of scenes read by one worker; scenes are dealt out to the
# slots as they free up, through xargs -P over the slot numbers.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%s\n' "${scenes[@]}" > "$work/scenes"
quoted_options=$(printf ' %q' "$@")
export regio_solve out_dir quoted_options work
printf '%s\n' "${hosts[@]}" | xargs -d '\n' -P "${#hosts[@]}" -I{} bash -c '
  host=$1
  # The next scene: a line taken from the shared list under a lock.
  next() { flock "$work/lock" bash -c "head -n1 \"$work/scenes\"; sed -i 1d \"$work/scenes\""; }
  while scene=$(next) && [ -n "$scene" ]; do
    command="$(printf %q "$regio_solve") solve -q --out-dir $(printf %q "$out_dir") --jobs 1 --threads 1$quoted_options -- $(printf %q "$scene")"
    if [ "$host" = ":" ]; then bash -c "$command"; else ssh -o BatchMode=yes "$host" "$command"; fi ||
      echo "$host: $scene: regio-solve exited with $?" >&2
  done' _ {} || true

"$regio_solve" summary --json "$out_dir/summary.json" "$out_dir" "${scenes[@]}"
