#!/usr/bin/env bash
# The cluster benchmark (scripts/bench cluster): starts a local single-node Slurm cluster (stopped
# on exit, pass or fail) and measures
#   1. the overhead of an array job: 16 tasks that do almost nothing, on Slurm and locally;
#   2. a reference render split into 1, 2, 4 and 8 tasks of one CPU each, against one process;
#   3. how long one class submission (all five stages) takes to build and grade on one core,
#      and from that, on paper, a class of 300 on a 20-node cluster of 32 cores per node.
# Needs root (slurmd), slurm-wlm and munge (scripts/install-deps).
set -euo pipefail
cd "$(dirname "$0")/.."
pathway=$PWD/build/release/pathway
scene=$PWD/scenes/cornell_box.gltf
state=$PWD/build/bench-slurm
work=$(mktemp -d)
trap 'scripts/slurm-cluster stop "$state" >/dev/null; rm -rf "$work"' EXIT
scripts/slurm-cluster start "$state" >/dev/null
export SLURM_CONF=$state/slurm.conf
cores=$(nproc)

seconds() { date +%s.%N; }
# Runs "$@" quietly; prints its wall time in seconds.
timed() {
  local start end
  start=$(seconds)
  "$@" >"$work/last.log" 2>&1 || { cat "$work/last.log" >&2; return 1; }
  end=$(seconds)
  python3 -c "print(f'{$end - $start:.2f}')"
}

echo "== 1. overhead of an array job: 16 tasks, each an 8x8 render of 1 spp (~0.03 s of work)"
tiny=(-- "$scene" -i stage1@ref --width 8)
for scheduler in slurm local; do
  t=$(timed "$pathway" cluster render -q --scheduler $scheduler --tasks 16 --spp 16 \
    --work-dir "$work/tiny-$scheduler" -o "$work/tiny-$scheduler.exr" "${tiny[@]}")
  echo "$scheduler: $t s for 16 tasks + the merge"
  eval "tiny_$scheduler=$t"
done
overhead=$(python3 -c "print(f'{($tiny_slurm - $tiny_local) * $cores / 16:.2f}')")
echo "per task on Slurm: $overhead s of a CPU slot more than locally" \
  "($(python3 -c "print(f'{($tiny_slurm - $tiny_local) / 16:.2f}')") s of wall time per task with $cores tasks at once)"

echo
echo "== 2. a reference render, stage5@ref 256x256, 256 spp, split into tasks of one CPU"
render=("$scene" -i stage5@ref --width 256)
one_thread=$(timed "$pathway" render -q "${render[@]}" --spp 256 --threads 1 -o "$work/one.exr")
all_threads=$(timed "$pathway" render -q "${render[@]}" --spp 256 -o "$work/all.exr")
echo "one process, 1 thread:        $one_thread s"
echo "one process, $cores threads:        $all_threads s  (speed-up $(python3 -c "print(f'{$one_thread / $all_threads:.2f}')"))"
for tasks in 1 2 4 8; do
  t=$(timed "$pathway" cluster render -q --scheduler slurm --tasks $tasks --spp 256 \
    --cpus-per-task 1 --work-dir "$work/ref-$tasks" -o "$work/ref-$tasks.exr" -- "${render[@]}")
  echo "Slurm, $tasks task(s) of 1 CPU:  $t s  (speed-up over 1 thread $(python3 -c "print(f'{$one_thread / $t:.2f}')"))"
done
echo "(this node has $cores cores: no split can be more than ${cores}x faster here)"

echo
echo "== 3. one submission (the solutions as a student's files), all five stages, on one core"
mkdir -p "$work/class/student"
cp solutions/*/*.cpp "$work/class/student/"
t=$(timed taskset -c 0 "$pathway" grade -q --submission "$work/class/student" --output "$work/graded")
build=$(awk -F'\t' '$1 == "buildSeconds" {print $2}' "$work/graded/submission.tsv")
grade=$(awk -F'\t' '$1 == "gradeSeconds" {print $2}' "$work/graded/submission.tsv")
echo "one submission on one core: $t s (build $build s, grading $grade s)"
python3 - "$t" "$overhead" "$cores" <<'EOF'
import math, sys
per_submission = float(sys.argv[1])  # seconds on one core, build included
overhead = float(sys.argv[2])        # a task's slot time on Slurm beyond its work (part 1)
here = int(sys.argv[3])              # cores of this machine
students, nodes, cores_per_node = 300, 20, 32
cores = nodes * cores_per_node
wave = 1.0  # the controller starts array tasks in about 1-second waves
# One task per submission, one core each: every submission runs at once (300 <= 640 cores).
# Then the class-table job, which starts a wave after the last task.
waves = math.ceil(students / cores)
one_each = waves * (per_submission + overhead) + 2 * wave
cpu_hours = students * (per_submission + overhead) / 3600
print(f"on paper, {students} submissions x 5 stages on {nodes} nodes x {cores_per_node} cores "
      f"({cores} cores), one task per submission on one core each: {waves} wave(s) of "
      f"{per_submission:.1f} s + {overhead:.1f} s overhead, then the table: about "
      f"{one_each:.0f} s of wall time ({cpu_hours:.1f} CPU-hours in all)")
print(f"the same class on this {here}-core machine, {here} submissions at a time: about "
      f"{students * per_submission / here / 60:.0f} min")
EOF
