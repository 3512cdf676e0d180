#!/usr/bin/env bash
# The sandbox benchmark (scripts/bench sandbox [ROUNDS]): what shutting student code in costs,
# measured as whole runs of the grader with --sandbox off and --sandbox auto, in turns, ROUNDS
# times each (default 5):
#   1. every grading case of the reference stages (pathway grade --grade-reference): the cost
#      per case, since each stage's cases render in one sandboxed child;
#   2. a class of 20 submissions (copies of solutions/), each built (the compiler sandboxed too)
#      and graded (pathway grade --submissions).
# Prints each run's wall time, the medians and the ratio auto / off, and what auto put in force.
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-5}
pathway=$PWD/build/release/pathway
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
chmod 711 "$work"  # the sandboxed children of a root grader run as nobody and pass through it
for i in $(seq -w 1 20); do
  mkdir -p "$work/class/student$i"
  cp solutions/*/*.cpp "$work/class/student$i/"
done
chmod -R a+rX "$work/class"
cases=$("$pathway" grade --list-cases | tail -n +2 | wc -l)

seconds() { date +%s.%N; }
timed() {
  local start end
  start=$(seconds)
  "$@" >"$work/last.log" 2>&1 || true  # a grade that loses points exits 1; the time counts
  end=$(seconds)
  python3 -c "print(f'{$end - $start:.3f}')"
}
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }

for what in cases class; do
  declare -a off=() auto=()
  for round in $(seq "$rounds"); do
    for mode in off auto; do
      rm -rf "$work/out"
      if [[ $what == cases ]]; then
        t=$(timed "$pathway" grade -q --grade-reference --sandbox "$mode" --report "$work/out")
      else
        t=$(timed "$pathway" grade -q --submissions "$work/class" --output "$work/out" --sandbox "$mode")
      fi
      [[ $mode == off ]] && off+=("$t") || auto+=("$t")
    done
  done
  m_off=$(median "${off[@]}")
  m_auto=$(median "${auto[@]}")
  if [[ $what == cases ]]; then
    echo "== 1. the reference stages on all $cases grading cases, $rounds rounds in turns"
  else
    echo "== 2. a class of 20 submissions built and graded ($((20 * cases)) cases), $rounds rounds in turns"
  fi
  echo "   off:  ${off[*]} s (median $m_off s)"
  echo "   auto: ${auto[*]} s (median $m_auto s)"
  python3 -c "
off, auto, n = $m_off, $m_auto, $cases * (10 if '$what' == 'class' else 1)
print(f'   auto / off = {auto / off:.3f}; {1000 * (auto - off) / n:+.1f} ms per case')"
done
echo "== in force (auto, this machine)"
grep -ho '"sandbox": "[^"]*' "$work/out/"*/results.json | head -n 1 | sed 's/^"sandbox": "/   /; s/\\n/\n   /g'
