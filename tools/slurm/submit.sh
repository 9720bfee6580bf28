#!/usr/bin/env bash
# Solves a directory of Regio scenes on a Slurm cluster: one scene per task
# of a job array, then a summary job once every task has ended.
#
#   tools/slurm/submit.sh [--cpus N] [--max-parallel N] [--partition P]
#                         [--time LIMIT] SCENE_DIR OUT_DIR [-- SOLVE OPTIONS...]
#
# SCENE_DIR's *.json files are listed into OUT_DIR/scenes.txt; task i solves
# line i + 1 with `regio-solve solve --out-dir OUT_DIR` and the SOLVE OPTIONS
# (--format glb,png, --hemicube 300, ...). OUT_DIR must be on a file system
# every node sees. The summary job writes OUT_DIR/summary.txt (the table)
# and OUT_DIR/summary.json. Submitting again resumes: scenes already solved
# with the same content and options are skipped in milliseconds.
#
# regio-solve is taken from $REGIO_SOLVE, else from PATH, on the nodes as
# here. docs/batch.md explains it all.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
cpus=1
max_parallel=
sbatch_args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --cpus) cpus=$2; shift 2 ;;
    --max-parallel) max_parallel=$2; shift 2 ;;
    --partition) sbatch_args+=(--partition "$2"); shift 2 ;;
    --time) sbatch_args+=(--time "$2"); shift 2 ;;
    -h|--help) sed -n '2,17p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    --) break ;;
    -*) echo "submit.sh: unknown option $1" >&2; exit 2 ;;
    *) break ;;
  esac
done
[ $# -ge 2 ] || { echo "usage: submit.sh [OPTIONS] SCENE_DIR OUT_DIR [-- SOLVE OPTIONS...]" >&2; exit 2; }
scene_dir=$1; out_dir=$2; shift 2
[ "${1:-}" = "--" ] && shift

regio_solve=${REGIO_SOLVE:-$(command -v regio-solve || true)}
[ -n "$regio_solve" ] && [ -x "$regio_solve" ] ||
  { echo "submit.sh: regio-solve not found: put it on PATH or set REGIO_SOLVE" >&2; exit 2; }
regio_solve=$(realpath "$regio_solve")

mkdir -p "$out_dir/slurm"
out_dir=$(realpath "$out_dir")
list="$out_dir/scenes.txt"
find "$(realpath "$scene_dir")" -maxdepth 1 -name '*.json' ! -name '*.report.json' | LC_ALL=C sort > "$list"
count=$(wc -l < "$list")
[ "$count" -gt 0 ] || { echo "submit.sh: no *.json scene in $scene_dir" >&2; exit 2; }

array="0-$((count - 1))${max_parallel:+%$max_parallel}"
array_job=$(sbatch --parsable --job-name=regio-solve --array="$array" --cpus-per-task="$cpus" \
  --output="$out_dir/slurm/%A_%a.out" --export=ALL,REGIO_SOLVE="$regio_solve" "${sbatch_args[@]}" \
  "$here/regio-array.sbatch" "$out_dir" "$list" "$@")
array_job=${array_job%%;*}
summary_job=$(sbatch --parsable --job-name=regio-summary --dependency=afterany:"$array_job" \
  --output="$out_dir/slurm/summary-%j.out" --export=ALL,REGIO_SOLVE="$regio_solve" "${sbatch_args[@]}" \
  "$here/regio-summary.sbatch" "$out_dir" "$list")
summary_job=${summary_job%%;*}
echo "submitted job array $array_job ($count scenes) and summary job $summary_job"
echo "results: $out_dir (summary.txt and summary.json once job $summary_job has run)"
