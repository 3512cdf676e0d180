#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image: install the Debian
# packages and build the grader (the program with the reference stages and the references).
# The autograder's files are in $AUTOGRADER_ROOT/source (Gradescope: /autograder/source).
set -euo pipefail
root=${AUTOGRADER_ROOT:-/autograder}
cd "$root/source"
bash scripts/install-deps --grader
bash scripts/build grader
# Student code runs beside these files: the solutions are compiled in, so their sources go, and
# the rest becomes read-only. The grading runs as an unprivileged user when this runs as root.
rm -rf solutions tests/mutants
chmod -R a-w,a+rX "$root/source"
if [[ $(id -u) == 0 ]] && ! id pathway-grader >/dev/null 2>&1; then
  useradd --system --no-create-home --shell /usr/sbin/nologin pathway-grader
fi
