#!/usr/bin/env bash
# Sets up what the peers benchmark (bench/peers/peers.py) needs, installing only what is missing,
# and prints the libLLVM path to give Dr.Jit as DRJIT_LIBLLVM_PATH:
#  - Debian's numpy and scipy (python3-numpy, python3-scipy: the statistics use scipy.stats);
#  - build/peers/venv (Debian's python3, so python3-venv) that sees them (--system-site-packages),
#    with mitsuba==3.9.1 from PyPI, which Debian does not package;
#  - Debian's libLLVM for Mitsuba's llvm_ad_rgb variant. Dr.Jit 1.5 (Mitsuba 3.9.1) refuses LLVM
#    older than 15, and Debian's LLVM 15 and 16 abort while compiling Mitsuba's path tracer on
#    x86-64 ("Cannot select ... fminimum": no instruction selection for llvm.minimum), so this
#    takes LLVM 17 or newer: Debian 12 has libllvm19.
# Messages go to stderr; the path alone to stdout. Usage: bench/peers/setup.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
venv=build/peers/venv
python=/usr/bin/python3  # Debian's: a pyenv or other python3 earlier on PATH may lack venv
mitsuba_version=3.9.1
llvm_package=libllvm19

say() { echo "peers setup: $*" >&2; }
fail() { say "$*"; exit 1; }
as_root() {
  if [[ $(id -u) == 0 ]]; then "$@"
  elif command -v sudo >/dev/null; then sudo "$@"
  else fail "'$*' needs root or sudo"; fi
}
apt_install() {
  say "installing $* with apt-get"
  # A fresh machine may have no package lists yet: update once, then try again.
  as_root apt-get install -y "$@" >/dev/null 2>&1 ||
    { as_root apt-get update >/dev/null && as_root apt-get install -y "$@" >/dev/null; } ||
    fail "could not install $* (apt-get install -y $*)"
}

[[ -x $python ]] || fail "$python not found: this needs Debian's python3"
"$python" -c "import numpy, scipy" 2>/dev/null || apt_install python3-numpy python3-scipy
# A venv made before it had to see Debian's packages (it held PyPI's numpy) is made again.
if [[ -x $venv/bin/python ]] && ! grep -qx "include-system-site-packages = true" "$venv/pyvenv.cfg"; then
  say "removing $venv: it was made without Debian's packages (--system-site-packages)"
  rm -rf "$venv"
fi
if [[ ! -x $venv/bin/python ]]; then
  "$python" -c "import venv, ensurepip" 2>/dev/null || apt_install python3-venv
  say "creating $venv"
  "$python" -m venv --system-site-packages "$venv" || fail "could not create $venv"
fi
if ! "$venv/bin/python" -c "import mitsuba; assert mitsuba.__version__ == '$mitsuba_version'" 2>/dev/null; then
  say "installing mitsuba==$mitsuba_version into $venv"
  "$venv/bin/python" -m pip install --quiet "mitsuba==$mitsuba_version" >&2 ||
    fail "pip could not install mitsuba==$mitsuba_version (is PyPI reachable?)"
fi

# The newest libLLVM of version 17 or later, unless DRJIT_LIBLLVM_PATH already names one.
find_llvm() {
  local best="" best_version=0 file version
  for file in /usr/lib/*-linux-gnu/libLLVM*.so*; do
    [[ -f $file ]] || continue
    version=$(basename "$file" | grep -oE '[0-9]+' | head -1) || continue
    if ((version >= 17 && version > best_version)); then best=$file best_version=$version; fi
  done
  echo "$best"
}
llvm=${DRJIT_LIBLLVM_PATH:-}
if [[ -z $llvm ]]; then
  llvm=$(find_llvm)
  if [[ -z $llvm ]]; then
    apt_install "$llvm_package"
    llvm=$(find_llvm)
  fi
fi
[[ -n $llvm && -f $llvm ]] || fail "no libLLVM 17 or newer found (apt-get install $llvm_package)"

# The real test: Mitsuba's path tracer compiled by this LLVM, on a tiny image.
job='{"variant": "llvm_ad_rgb", "scene": "scenes/cornell_box.gltf", "width": 8, "height": 8,
      "max_depth": 6, "rr_depth": 3, "renders": [{"spp": 4, "seed": 0}]}'
if ! DRJIT_LIBLLVM_PATH=$llvm "$venv/bin/python" bench/peers/mitsuba_worker.py "$job" >/dev/null 2>/tmp/peers-llvm-check.$$; then
  { grep -m1 -E "LLVM ERROR|Error" /tmp/peers-llvm-check.$$ || tail -3 /tmp/peers-llvm-check.$$; } >&2
  rm -f /tmp/peers-llvm-check.$$
  fail "Mitsuba llvm_ad_rgb does not work with $llvm (set DRJIT_LIBLLVM_PATH to libLLVM 17 or newer)"
fi
rm -f /tmp/peers-llvm-check.$$
say "ready: $venv, DRJIT_LIBLLVM_PATH=$llvm"
echo "$llvm"
