#!/usr/bin/env bash
# Where a fresh clone's `make test` (what CI's .ci/run runs) spends its time, and the cold start:
# clone the repository into DIR, then time, each with /usr/bin/time (wall, and user + sys CPU of
# the command and the children it waited for):
#   setup        scripts/setup.sh (venv, pip install, `python -m dmdvox.warm`)
#   demo 1, 2    the first `dmdvox demo` after setup, and a second one
#   cold         `dmdvox simulate` of the demo with an empty numba cache (--cold only: 4 min of CPU)
#   suite        the tests as `make test` runs them
#   wheel        scripts/test_wheel.sh
# On a shared machine the wall times grow with the load and the CPU times much less: read both.
# Usage: scripts/bench_ci.sh [--cold] [DIR]   (DIR defaults to /tmp/dmdvox-ci-bench; removed first)
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cold=0
if [[ "${1:-}" == "--cold" ]]; then
    cold=1
    shift
fi
dir="${1:-/tmp/dmdvox-ci-bench}"
rm -rf "$dir"
git clone -q "$repo" "$dir"
cd "$dir"
times="$dir/.bench-times"
: >"$times"

measure() {  # LABEL COMMAND...: run it, its output in DIR/LABEL.log, one line of figures in $times
    local label="$1"
    shift
    /usr/bin/time -a -o "$times" -f "$label %e %U %S" "$@" >"$dir/$label.log" 2>&1 || {
        echo "bench_ci: $label failed: $dir/$label.log" >&2
        exit 1
    }
}

measure setup bash scripts/setup.sh
measure demo1 .venv/bin/dmdvox demo --out "$dir/demo1" --json
measure demo2 .venv/bin/dmdvox demo --out "$dir/demo2" --json
if ((cold)); then
    empty="$(mktemp -d)"
    measure cold env NUMBA_CACHE_DIR="$empty" .venv/bin/dmdvox simulate data/demo_block.gcode --json
    rm -rf "$empty"
fi
measure suite make -o setup test-suite
measure wheel bash scripts/test_wheel.sh

echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
awk '{printf "%-6s wall %7.1f s   CPU %7.1f s\n", $1, $2, $3 + $4}' "$times"
grep -h "warm: done\|passed\|failed" "$dir/setup.log" "$dir/suite.log" | tail -n 3
