#!/usr/bin/env bash
# The pictures of docs/guide.md, made by the programs themselves from the
# sample scenes: `regio --screenshot` for the editor's window (on a virtual X
# server when there is no display) and `regio-solve --image` for a solved
# picture. Never edit the pictures by hand: change this script and run it.
#
#   scripts/guide-screenshots.sh [BUILD_DIR]      default: build
#   cmake --build build --target guide_screenshots  (the same)
#
# Writes docs/images/guide/*.png.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
out="$root/docs/images/guide"
scenes="$root/resources/scenes"
regio="$build/editor/regio"
solve="$build/cli/regio-solve"
for program in "$regio" "$solve"; do
  [ -x "$program" ] || { echo "guide-screenshots: $program is not built" >&2; exit 2; }
done
mkdir -p "$out"

# One window picture: FILE SCENE [regio options...]. English, whatever the
# machine's locale, so that the pictures match the guide's text.
window() {
  local file=$1 scene=$2
  shift 2
  local run=("$regio" "$scene" --lang en --size 1280x800 --screenshot "$out/$file" "$@")
  if [ -n "${DISPLAY:-}" ]; then
    "${run[@]}"
  else
    xvfb-run -a -s "-screen 0 1600x1000x24" "${run[@]}"
  fi
  echo "  $out/$file"
}

echo "guide-screenshots: the editor"
window window.png "$scenes/two-lights-room.json"
window preview.png "$scenes/two-lights-room.json" --preview-iterations 2000 --panel Solver
window regions.png "$scenes/two-lights-room.json" --panel Regions
window bsp-order.png "$scenes/two-lights-room.json" --panel BspOrder
window cornell-preview.png "$scenes/cornell-box.json" --preview-iterations 2500 --panel Solver

echo "guide-screenshots: regio-solve"
"$solve" solve "$scenes/cornell-box.json" --quiet --image "$out/cornell-solved.png" --size 640x480
echo "  $out/cornell-solved.png"
