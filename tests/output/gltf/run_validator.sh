#!/bin/sh
# ctest entry of the glTF validation: runs validate.js with Node.js over the
# folder of sample exports ($1). Exit 77 (ctest: skipped) with the reason
# printed when Node.js is not installed; validate.js does the same when the
# validator package is missing.
here=${0%/*}
if ! command -v node >/dev/null 2>&1; then
    echo "SKIPPED: Node.js is not installed, so the Khronos glTF validator cannot run."
    echo "Install Debian's nodejs and npm, then: npm ci --prefix $here (scripts/dev.sh does this)."
    exit 77
fi
exec node "$here/validate.js" "$1"
