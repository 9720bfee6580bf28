#!/usr/bin/env bash
# Regio's one-stop developer script. On a fresh Debian 12 machine (as root, or
# with sudo) it installs whatever is missing from Debian's packages, configures
# and builds, then either opens the editor or runs the whole test suite.
# Idempotent: a second run installs nothing and rebuilds only what changed.
#
#   scripts/dev.sh run [SCENE.json] [editor args...]   build, open the editor
#   scripts/dev.sh test [ctest args...]                 build, run every test, then
#                                                       fuzz the reader and the
#                                                       solver 45 s each
#                                                       (REGIO_FUZZ_SECONDS)
#   scripts/dev.sh build                                build only
#   scripts/dev.sh bench [benchmark args...]            Release build, every benchmark
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="${REGIO_BUILD_DIR:-$root/build}"

# Everything Regio needs, from Debian 12's archive only.
packages=(
  g++ cmake ninja-build pkg-config dpkg-dev clang libclang-rt-14-dev
  qt6-base-dev libqt6opengl6-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-translations-l10n
  qt6-charts-dev
  libglm-dev nlohmann-json3-dev libstb-dev libpng-dev libssl-dev libassimp-dev assimp-testmodels
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth libgl-dev libgl1-mesa-dri fonts-dejavu-core
  python3 python3-jsonschema
)

install_missing() {
  local missing=()
  # Node.js runs the Khronos glTF validator in the tests. A machine that
  # already has a Node.js (e.g. from another repository) keeps it: Debian's
  # npm package would conflict with it.
  command -v npm >/dev/null 2>&1 || packages+=(nodejs npm)
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "regio: installing ${missing[*]}" >&2
  local sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

configure_and_build() {
  if [ ! -f "$build/build.ninja" ]; then
    # The dev preset (CMakePresets.json): everything, warnings are errors.
    (cd "$root" && cmake --preset dev -B "$build")
  fi
  cmake --build "$build"
}

command=${1:-}
[ $# -gt 0 ] && shift
case "$command" in
  run)
    install_missing
    configure_and_build
    scene="$root/resources/scenes/two-lights-room.json"
    if [ $# -gt 0 ] && [[ "$1" != -* ]]; then scene=$1; shift; fi
    if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
      # No screen: still useful with --screenshot, so run on a virtual one.
      echo "regio: no display; running on a virtual X server (xvfb-run)" >&2
      exec xvfb-run -a -s "-screen 0 1920x1200x24" "$build/editor/regio" "$scene" "$@"
    fi
    exec "$build/editor/regio" "$scene" "$@"
    ;;
  test)
    install_missing
    configure_and_build
    # The glTF validator (npm package gltf-validator) at the versions the
    # committed lockfile pins.
    gltf="$root/tests/output/gltf"
    [ -d "$gltf/node_modules/gltf-validator" ] || npm ci --prefix "$gltf" --no-audit --no-fund
    ctest --test-dir "$build" --output-on-failure -j2 "$@"
    # Then the fuzz harnesses of Regio's own code for a while (clang, ASan +
    # UBSan; build-fuzz/), unless ctest was asked for a part only or
    # REGIO_FUZZ_SECONDS=0. The importer's harness also reaches Assimp, which
    # still aborts on some broken files (docs/reliability.md): run it with
    # scripts/fuzz.sh SECONDS importer_fuzzer.
    seconds=${REGIO_FUZZ_SECONDS:-45}
    if [ $# -eq 0 ] && [ "$seconds" -gt 0 ]; then
      "$root/scripts/fuzz.sh" "$seconds" scene_reader_fuzzer prepare_fuzzer
    fi
    ;;
  build)
    install_missing
    configure_and_build
    ;;
  bench)
    # The release preset (CMakePresets.json): Release, benchmarks only. The
    # figures go to build-release/bench/, with the plot of a shot's cost
    # (docs/performance.md says what each benchmark measures).
    packages+=(gnuplot-nox) # the plot
    install_missing
    (cd "$root" && cmake --preset release >/dev/null && cmake --build --preset release)
    out="$root/build-release/bench"
    mkdir -p "$out"
    for bench in table1_bench adaptive_bench speed_bench; do
      "$root/build-release/tests/bench/$bench" --benchmark_out="$out/$bench.json" --benchmark_out_format=json "$@" \
        | tee "$out/$bench.txt"
    done
    python3 "$root/scripts/plot_speed.py" "$out/speed_bench.json" "$out/shot-cost.png" \
      && echo "regio: plot in $out/shot-cost.png" >&2
    ;;
  *)
    echo "usage: scripts/dev.sh run [SCENE.json] [editor args...] | test [ctest args...] | build | bench [args...]" >&2
    exit 2
    ;;
esac
