#!/usr/bin/env bash
# The Debian packages as a user meets them: CPack builds regio-solve and
# regio from this build, their file lists and dependencies are what a batch
# machine and a desktop need (regio-solve without Qt), dpkg installs them
# into a scratch root, and the installed commands work there: regio-solve
# solves an installed sample, the editor reports its version, the batch
# scripts are in place. apt-get checks (as a simulation) that every
# dependency is in Debian's archive.
#   package_test.sh BUILD_DIR
set -euo pipefail
build=$1
work=$(mktemp -d /tmp/regio-package-test.XXXXXX)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }

cpack --config "$build/CPackConfig.cmake" -G DEB -B "$work/packages" > "$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log"; fail "cpack could not build the packages"; }
solve_deb=$(ls "$work"/packages/regio-solve_*_amd64.deb "$work"/packages/regio-solve_*.deb 2>/dev/null | head -1)
editor_deb=$(ls "$work"/packages/regio_*.deb 2>/dev/null | head -1)
[ -f "$solve_deb" ] || fail "no regio-solve package"
[ -f "$editor_deb" ] || fail "no regio package"

files() { dpkg-deb -c "$1" | awk '{print $6}' | sed 's|^\./|/|'; }
files "$solve_deb" > "$work/solve.files"
files "$editor_deb" > "$work/editor.files"
for f in /usr/bin/regio-solve /usr/share/regio/scenes/cornell-box.json /usr/share/regio/scenes/two-lights-room.json \
         /usr/share/regio/schema/regio-scene.schema.json /usr/share/regio/tools/slurm/submit.sh \
         /usr/share/regio/tools/slurm/regio-array.sbatch /usr/share/regio/tools/slurm/regio-summary.sbatch \
         /usr/share/regio/tools/ssh/solve-over-ssh.sh /usr/share/doc/regio-solve/README.md \
         /usr/share/doc/regio-solve/batch.md; do
  grep -qx "$f" "$work/solve.files" || fail "regio-solve does not install $f"
done
for f in /usr/bin/regio /usr/share/applications/regio.desktop /usr/share/icons/hicolor/scalable/apps/regio.svg; do
  grep -qx "$f" "$work/editor.files" || fail "regio does not install $f"
done
solve_depends=$(dpkg-deb -f "$solve_deb" Depends)
editor_depends=$(dpkg-deb -f "$editor_deb" Depends)
echo "regio-solve depends on: $solve_depends"
echo "regio depends on: $editor_depends"
case "$solve_depends" in *qt*|*Qt*) fail "the headless package depends on Qt";; esac
case "$editor_depends" in *"regio-solve (= "*) ;; *) fail "regio does not depend on its regio-solve";; esac
case "$editor_depends" in *libqt6widgets6*) ;; *) fail "regio does not depend on Qt Widgets";; esac

# Installed with dpkg into a scratch root (dependencies come from this
# machine, which the simulation below checks against the archive).
root="$work/root"
mkdir -p "$root/var/lib/dpkg/updates" "$root/var/lib/dpkg/info"
touch "$root/var/lib/dpkg/status"
dpkg --root="$root" --force-depends --force-script-chrootless -i "$solve_deb" "$editor_deb" > "$work/dpkg.log" 2>&1 ||
  { cat "$work/dpkg.log"; fail "dpkg could not install the packages"; }
"$root/usr/bin/regio-solve" --version | grep -q "^regio-solve " || fail "the installed regio-solve has no version"
"$root/usr/bin/regio-solve" solve -q --iterations 5 --report "$work/report.json" \
  "$root/usr/share/regio/scenes/cornell-box.json" || fail "the installed regio-solve cannot solve an installed sample"
grep -q '"iterations": 5' "$work/report.json" || fail "the installed sample was not solved"
QT_QPA_PLATFORM=offscreen "$root/usr/bin/regio" --version 2>/dev/null | grep -q "^Regio " ||
  fail "the installed editor does not report its version"
"$root/usr/share/regio/tools/slurm/submit.sh" --help | grep -q "job array" || fail "submit.sh is not usable"

# Every dependency resolvable from Debian's archive (a simulation: nothing
# is installed). Skipped where apt has no package lists.
if command -v apt-get >/dev/null && [ -n "$(ls /var/lib/apt/lists 2>/dev/null | grep -v -e lock -e partial)" ]; then
  apt-get install -s "$solve_deb" "$editor_deb" > "$work/apt.log" 2>&1 ||
    { cat "$work/apt.log"; fail "apt cannot resolve the packages' dependencies"; }
  grep -q "^Inst regio " "$work/apt.log" || { cat "$work/apt.log"; fail "apt would not install regio"; }
else
  echo "note: apt has no package lists here; the dependencies were not checked against the archive"
fi
echo "both packages install and work: $(basename "$solve_deb"), $(basename "$editor_deb")"
