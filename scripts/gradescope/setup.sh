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
# the rest becomes read-only. The references (the course's own among them) stay readable to the
# grader alone: student code compiles and renders as the user nobody, inside the sandbox.
rm -rf solutions tests/mutants
chmod -R a-w,a+rX "$root/source"
chmod -R go-rwx "$root/source/scenes/references"
