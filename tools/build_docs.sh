#!/usr/bin/env bash
# The plugin's manual as HTML: doc/ -> build/html (open build/html/index.html).
# Every Sphinx warning is an error (-W), as in LAMMPS's own doc build; LAMMPS's pages
# are checked against the LAMMPS source tree the plugin was built with (doc/conf.py).
#   bash tools/build_docs.sh [OUTPUT-FOLDER]
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=${1:-${CLUSTERDYN_BUILD_DIR:-$top/build}/html}
command -v sphinx-build >/dev/null || { echo "no sphinx-build: run tools/bootstrap.sh (python3-sphinx)"; exit 1; }
exec sphinx-build -b html -W --keep-going -q -d "$out/.doctrees" "$top/doc" "$out"
