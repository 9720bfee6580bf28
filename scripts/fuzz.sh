#!/usr/bin/env bash
# Builds the libFuzzer harnesses (tests/fuzz, the fuzz preset: clang with
# ASan + UBSan) and runs each for the given time, one after another.
#
#   scripts/fuzz.sh [SECONDS [HARNESS...]]     default: 60 s each, every harness
#
# Each harness keeps its corpus in build-fuzz/corpus/NAME (grown run after
# run) and starts from seeds in the repository: the sample scenes, the
# valid scenes and the bad-file catalogue for the reader; small models of
# Debian's assimp-testmodels for the importer. A finding (a crash, a
# sanitizer report, a failed check) stops the run and leaves the input as
# build-fuzz/findings/NAME/crash-*: turn it into a regression test
# (docs/reliability.md). The last line of each run gives its executions and
# coverage. Exit status: 0 no finding, 1 a finding, 2 the build failed.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="$root/build-fuzz"
seconds=${1:-60}
[ $# -gt 0 ] && shift
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=(scene_reader_fuzzer prepare_fuzzer importer_fuzzer)

command -v clang++ >/dev/null || { echo "fuzz.sh: clang++ is needed (apt-get install clang)" >&2; exit 2; }
if [ ! -f "$build/build.ninja" ]; then
  (cd "$root" && cmake --preset fuzz > /dev/null) || exit 2
fi
cmake --build "$build" --target "${harnesses[@]}" > "$build/fuzz-build.log" 2>&1 ||
  { tail -30 "$build/fuzz-build.log"; exit 2; }

# Seeds: read-only corpus directories handed to libFuzzer after the first.
seeds_for() {
  case "$1" in
    scene_reader_fuzzer)
      echo "$root/resources/scenes $root/tests/data/valid $root/tests/data/bad" ;;
    prepare_fuzzer)
      echo "$root/tests/fuzz/seeds/prepare" ;;
    importer_fuzzer)
      # A byte that picks the format, then a small model of that format.
      local dir="$build/seeds/importer"
      if [ ! -d "$dir" ]; then
        mkdir -p "$dir"
        local i=0
        for ext in obj gltf glb ply stl off dae 3ds; do
          find /usr/share/assimp/models -iname "*.$ext" -size -12k 2>/dev/null | LC_ALL=C sort | head -4 |
            while read -r model; do
              { printf "\\$(printf %03o "$i")"; cat "$model"; } > "$dir/$ext-$(basename "$model")"
            done
          i=$((i + 1))
        done
      fi
      echo "$dir" ;;
  esac
}

# Leaks inside system libraries (Assimp's, on some broken files) are not
# Regio's to fix: tests/sanitizers/lsan.supp lists them.
export LSAN_OPTIONS="suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# The importer's harness throws std::bad_alloc where malloc fails
# (tests/fuzz/throwing_new.cpp), as new does outside ASan; a broken model
# file that asks Assimp for 40 GB is then an unreadable file, not a crash.
# Requests beyond 3 GB fail at once, below libFuzzer's own limit on one
# allocation (-rss_limit_mb), which would count them as findings.
export ASAN_OPTIONS="allocator_may_return_null=1:max_allocation_size_mb=3072"
status=0
for name in "${harnesses[@]}"; do
  corpus="$build/corpus/$name"
  findings="$build/findings/$name"
  mkdir -p "$corpus" "$findings"
  echo "== $name, $seconds s"
  # shellcheck disable=SC2046
  if ! (cd "$findings" && "$build/tests/fuzz/$name" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=4096 \
          -max_len=65536 -print_final_stats=1 "$corpus" $(seeds_for "$name") > "$findings/last-run.log" 2>&1); then
    grep -E "ERROR|SUMMARY|Test unit written|DEADLYSIGNAL" "$findings/last-run.log" | head -20
    status=1
  fi
  grep -E "^#[0-9]+ *DONE|^stat::number_of_executed_units|^stat::peak_rss_mb" "$findings/last-run.log" | tail -3 || true
  grep -E "cov: [0-9]+" "$findings/last-run.log" | tail -1 | sed 's/^/  last: /' || true
done
exit $status
