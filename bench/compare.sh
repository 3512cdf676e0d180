#!/usr/bin/env bash
# Before and after: every stage rendered by the program at an earlier commit and by the working
# tree, in turns (ABBA, so neither always goes first), so both see the same machine load. Prints
# each stage's mean user CPU seconds and wall seconds, and after / before. User CPU time is the
# steadier figure on a busy machine.
# Usage: bench/compare.sh REV [RUNS]   (REV: any commit, e.g. HEAD~1; RUNS: per stage, default 5)
# The earlier program stays in build/compare/<commit> for the next comparison; remove it with
# `git worktree remove --force build/compare/<commit>`.
set -euo pipefail
cd "$(dirname "$0")/.."
rev=${1:?usage: bench/compare.sh REV [RUNS]}
runs=${2:-5}
if ! commit=$(git rev-parse --verify --quiet "$rev^{commit}"); then
  echo "bench/compare.sh: '$rev' is not a commit of this repository" >&2
  exit 2
fi
if ! [[ $runs =~ ^[1-9][0-9]*$ ]]; then
  echo "bench/compare.sh: RUNS must be a positive whole number, not '$runs'" >&2
  exit 2
fi

# The earlier program, built once per commit in a worktree of its own (its build refers to files
# of its own tree, such as the image-file module) and kept: build/compare/<commit>.
sources=build/compare/$commit
before=$sources/build/release/pathway
if [[ ! -x $before ]]; then
  echo "building $rev ($commit) in $sources ..." >&2
  rm -rf "$sources"
  git worktree prune
  git worktree add --detach --force "$sources" "$commit" >/dev/null
  # The same preset as the working tree's program: the viewer's libraries alone change start-up.
  if ! (cd "$sources" && cmake --preset release >/dev/null &&
    cmake --build --preset release --target pathway >/dev/null); then
    echo "bench/compare.sh: building $rev ($commit) in $sources failed" >&2
    exit 1
  fi
fi
scripts/build release >/dev/null  # the working tree's program, up to date
after=build/release/pathway

scene=scenes/cornell_box.gltf
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "before: $rev ($commit); after: the working tree (release preset)"
echo "each: pathway render $scene -i STAGE --width 256 --spp 64, $runs runs, in turns"
printf '%-12s %14s %14s %10s %12s %12s %10s\n' integrator "user s before" "user s after" \
  "after/bef" "wall before" "wall after" "after/bef"
TIMEFORMAT='%U %R'
for stage in stage1@ref stage2@ref stage3@ref stage4@ref stage5@ref; do
  : >"$out/times"
  for ((i = 0; i < runs; ++i)); do
    order="before after"
    ((i % 2 == 1)) && order="after before"
    for side in $order; do
      program=$before
      [[ $side == after ]] && program=$after
      # bash's `time` keyword: no extra package; its report goes to stderr of the group.
      { time "$program" render "$scene" -i "$stage" --width 256 --spp 64 -q \
        -o "$out/$side.exr" >/dev/null 2>"$out/err"; } 2>"$out/time" ||
        { echo "bench/compare.sh: $side failed on $stage:" >&2; cat "$out/err" >&2; exit 1; }
      echo "$side $(cat "$out/time")" >>"$out/times"
    done
  done
  awk -v stage="$stage" '
    { user[$1] += $2; wall[$1] += $3; n[$1]++ }
    END {
      ub = user["before"] / n["before"]; ua = user["after"] / n["after"]
      wb = wall["before"] / n["before"]; wa = wall["after"] / n["after"]
      printf "%-12s %14.3f %14.3f %10.3f %12.3f %12.3f %10.3f\n", stage, ub, ua, ua / ub, wb, wa, wa / wb
    }' "$out/times"
done
