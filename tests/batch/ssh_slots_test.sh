#!/usr/bin/env bash
# tools/ssh/solve-over-ssh.sh with two slots on this machine (":" runs
# without ssh): four scenes solved, the summary lists them, and a second run
# solves nothing again.
#   ssh_slots_test.sh REGIO_SOLVE SOURCE_DIR
set -euo pipefail
regio_solve=$1; source_dir=$2
work=$(mktemp -d /tmp/regio-ssh-test.XXXXXX)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }

"$regio_solve" sweep "$source_dir/resources/scenes/cornell-box.json" --set solver.hemicube=40,50,60,70 \
  --out-dir "$work/scenes" -q
printf '# two slots here\n:\n:\n' > "$work/hosts"
run() {
  REGIO_SOLVE=$regio_solve "$source_dir/tools/ssh/solve-over-ssh.sh" "$work/hosts" "$work/scenes" "$work/out" -- \
    --iterations 20 --adaptive off --format ply
}
run | tee "$work/first.txt"
grep -q "^4 scenes: 4 solved, 0 skipped, 0 failed" "$work/first.txt" || fail "the summary does not list four solved scenes"
for n in 001 002 003 004; do
  [ -s "$work/out/cornell-box-$n.ply" ] || fail "no model for cornell-box-$n"
done
before=$(stat -c %Y "$work/out/cornell-box-001.report.json")
sleep 1
run > "$work/second.txt"
[ "$(stat -c %Y "$work/out/cornell-box-001.report.json")" = "$before" ] || fail "the second run solved again"
echo "two slots solved four scenes; the second run solved none again"
